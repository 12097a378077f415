// The property at the heart of the project: for hundreds of random scenes from fixed seeds, the
// CPU twin's image equals lavapipe's, 0 differing pixels. A failing scene is written out so it can
// be replayed with `twinraster render`.
#include "chain/draw_list.hpp"
#include "random_scene.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <filesystem>

using namespace twinraster;

namespace {

constexpr std::uint32_t kFirstSeed = 1;
constexpr std::uint32_t kSceneCount = 1000;

std::filesystem::path SaveFailure(const std::string& name, const std::string& json_text) {
  const std::filesystem::path dir = std::filesystem::path(TWINRASTER_BINARY_DIR) / "failed-scenes";
  std::filesystem::create_directories(dir);
  const auto file = dir / (name + ".json");
  test::WriteFile(file, json_text);
  return file;
}

// Renders the random scenes (as wireframes when asked) on both backends and fails on any
// difference, writing each failing scene out for `twinraster render`.
void RequireRandomScenesEqual(bool wireframe) {
  // Created outside the loop so that their set-up is not charged to a scene.
  test::SharedGpu(gpu::Instancing::kNever);
  test::SharedGpu(gpu::Instancing::kAlways);
  const std::string kind = wireframe ? "random-wireframe-" : "random-";
  std::uint32_t failures = 0, scenes_with_drawing = 0;
  for (std::uint32_t seed = kFirstSeed; seed < kFirstSeed + kSceneCount; ++seed) {
    nlohmann::ordered_json json = test::RandomSceneJson(seed);
    if (wireframe) json["wireframe"] = true;
    const std::string text = json.dump(1);
    const Scene scene = ParseScene(text, kind + std::to_string(seed) + ".json");
    REQUIRE(scene.wireframe == wireframe);
    const test::TwinResult r = test::RenderTwins(BuildDrawList(scene));
    scenes_with_drawing += test::CountNotColour(r.cpu, scene.canvas.background) > 0 ? 1 : 0;
    if (r.Equal()) continue;
    ++failures;
    const auto file = SaveFailure(kind + std::to_string(seed), text);
    UNSCOPED_INFO("seed " << seed << ": " << r.Describe() << "\n  replay: twinraster render " << file.string());
    CHECK(r.Equal());
  }
  REQUIRE(failures == 0);
  // Guards the generator: scenes that draw nothing would make the comparison meaningless.
  INFO(scenes_with_drawing << " of " << kSceneCount << " scenes drew something");
  REQUIRE(scenes_with_drawing >= kSceneCount * 8 / 10);
  test::RequireNoValidationMessages();
}

}  // namespace

TEST_CASE("Random scenes: GPU image == CPU image in every one", "[twin][random]") { RequireRandomScenesEqual(false); }

TEST_CASE("Random scenes in wireframe: GPU image == CPU image in every one", "[twin][random][wireframe]") {
  // The same scenes drawn as triangle edges (polygonMode LINE): clipped polygons, edges along
  // clip planes left out, cameras inside the cloud, every winding.
  RequireRandomScenesEqual(true);
}
