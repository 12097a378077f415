// Every shipped scene loads, and the chapter's demos carry the demo code's exact numbers.
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

using namespace twinraster;

TEST_CASE("Every shipped scene loads", "[scenes]") {
  const auto scenes = test::ShippedScenes();
  REQUIRE(scenes.size() >= 5);
  for (const auto& file : scenes) {
    INFO(file.string());
    const Scene scene = LoadScene(file);
    REQUIRE(!scene.instances.empty());
    REQUIRE(scene.name == file.stem().string());
  }
}

TEST_CASE("The chapter's demo scenes have the demo code's numbers", "[scenes]") {
  const Scene transforms = LoadScene(test::SourcePath("scenes/cgfs-transforms.json"));
  REQUIRE(transforms.canvas.width == 600);
  REQUIRE(transforms.canvas.height == 600);
  REQUIRE(transforms.camera.position == glm::dvec3(-3, 1, 2));
  REQUIRE(transforms.instances.size() == 2);
  REQUIRE(transforms.instances[0].transform.scale == glm::dvec3(0.75));
  REQUIRE(transforms.instances[1].transform.translation == glm::dvec3(1.25, 2.5, 7.5));  // the demo's 2.5

  const Scene instances = LoadScene(test::SourcePath("scenes/cgfs-instances.json"));
  REQUIRE(instances.instances[1].transform.translation == glm::dvec3(1.25, 2, 7.5));
  const Model& cube = instances.models[0];
  REQUIRE(cube.vertices.size() == 8);
  REQUIRE(cube.triangles.size() == 12);
  REQUIRE(cube.triangles[2].v == std::array<std::uint32_t, 3>{4, 0, 3});
  REQUIRE(cube.triangles[2].colour == Rgb8{0, 255, 0});
}
