// The draw list as the GPU process receives it: every field, vertex colours included, comes back
// as it went, and bytes that are not one whole list are refused.
#include "gpu/draw_list_wire.hpp"

#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <stdexcept>
#include <string>

using namespace twinraster;

TEST_CASE("The draw-list wire carries vertex colours, light and geometry unchanged", "[gpu][wire][vertex-colours]") {
  const DrawList list = BuildDrawList(LoadScene(test::SourcePath("scenes/lit-vertex-colours.json")));
  REQUIRE(list.meshes.size() == 3);
  REQUIRE(list.lighting.has_value());
  const std::string bytes = gpu::EncodeDrawList(list);
  const DrawList back = gpu::DecodeDrawList(bytes);
  REQUIRE(back.meshes.size() == list.meshes.size());
  for (std::size_t m = 0; m < list.meshes.size(); ++m) {
    INFO("mesh " << m);
    CHECK(back.meshes[m].vertex_colours.size() == 8);
    CHECK(back.meshes[m].vertex_colours == list.meshes[m].vertex_colours);
    CHECK(back.meshes[m].colours == list.meshes[m].colours);
    CHECK(back.meshes[m].shading == list.meshes[m].shading);
    CHECK(back.meshes[m].positions == list.meshes[m].positions);
  }
  CHECK(back.lighting->instances.size() == list.draws.size());
  CHECK(gpu::EncodeDrawList(back) == bytes);
  // Cut short by one byte, or one byte too long: not a list.
  CHECK_THROWS_AS(gpu::DecodeDrawList(bytes.substr(0, bytes.size() - 1)), std::invalid_argument);
  CHECK_THROWS_AS(gpu::DecodeDrawList(bytes + "x"), std::invalid_argument);
}
