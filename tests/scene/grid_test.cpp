// Grids of instances: an instance with "grid" stands for nx·ny·nz copies, centred on its own
// translation, i fastest, each keeping the instance's scale and rotation.
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <string>

using namespace twinraster;

namespace {

std::string GridScene(const std::string& instances) {
  return R"({"canvas": {"width": 64, "height": 48}, "viewport": {"width": 1, "height": 1, "distance": 1},
             "camera": {"position": [0, 0, 0]},
             "models": {"tri": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2, "red"]]}},
             "instances": )" +
         instances + "}";
}

}  // namespace

TEST_CASE("A grid's copies: centred offsets, i fastest, scale and rotation kept", "[scenes][grid]") {
  const Scene scene = ParseScene(GridScene(R"([
      {"model": "tri"},
      {"model": "tri", "transform": {"scale": 2, "rotation": {"axis": "y", "degrees": 30}, "translation": [10, 20, 30]},
       "grid": {"count": [3, 2, 2], "spacing": [1, 2, 3]}},
      {"model": "tri", "transform": {"translation": [5, 5, 5]}}])"),
                                 "grid.json");
  REQUIRE(scene.instances.size() == 1 + 12 + 1);
  REQUIRE(scene.grids.size() == 1);
  const InstanceGrid& grid = scene.grids[0];
  REQUIRE(grid.written == 1);
  REQUIRE(grid.first == 1);
  REQUIRE(grid.copies() == 12);
  const Instance& base = scene.instances[1];
  REQUIRE(base.transform.translation == glm::dvec3(10 - 1, 20 - 1, 30 - 1.5));
  for (std::uint32_t k = 0; k < 2; ++k)
    for (std::uint32_t j = 0; j < 2; ++j)
      for (std::uint32_t i = 0; i < 3; ++i) {
        const Instance& copy = scene.instances[1 + i + 3 * (j + 2 * k)];
        INFO("copy " << i << ", " << j << ", " << k);
        REQUIRE(copy.transform.translation == glm::dvec3(9.0 + i, 19.0 + 2.0 * j, 28.5 + 3.0 * k));
        REQUIRE(copy.transform.scale == glm::dvec3(2, 2, 2));
        REQUIRE(copy.transform.rotation == base.transform.rotation);
      }
  REQUIRE(scene.instances.back().transform.translation == glm::dvec3(5, 5, 5));
}

TEST_CASE("The grid scenes: Catlike's 10^3 grid and the chapter's million cubes", "[scenes][grid]") {
  const Scene catlike = LoadScene(test::SourcePath("scenes/catlike-grid.json"));
  REQUIRE(catlike.instances.size() == 1000);
  REQUIRE(catlike.instances.front().transform.translation == glm::dvec3(-4.5, -4.5, -4.5));
  REQUIRE(catlike.instances.back().transform.translation == glm::dvec3(4.5, 4.5, 4.5));
  REQUIRE(std::filesystem::file_size(test::SourcePath("scenes/one-million-cubes.json")) < 16 * 1024);
  const auto large = test::LargeShippedScenes();
  REQUIRE(large.size() == 1);
  const Scene million = LoadScene(large[0]);
  REQUIRE(million.instances.size() == 1'000'000);
  REQUIRE(million.grids.size() == 1);
  REQUIRE(million.models[0].triangles.size() * million.instances.size() == 12'000'000);
  REQUIRE(million.instances[1].transform.translation - million.instances[0].transform.translation ==
          glm::dvec3(1, 0, 0));
  REQUIRE(million.instances[100].transform.translation - million.instances[0].transform.translation ==
          glm::dvec3(0, 1, 0));
}
