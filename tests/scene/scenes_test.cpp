// Every shipped scene loads, and the chapter's demos carry the demo code's exact numbers.
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <string>

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

// `text` with every `from` replaced by `to`.
static std::string ReplaceAll(std::string text, const std::string& from, const std::string& to) {
  for (std::size_t at = text.find(from); at != std::string::npos; at = text.find(from, at + to.size())) {
    text.replace(at, from.size(), to);
  }
  return text;
}

TEST_CASE("A byte-order mark, and axis and colour names in capitals, read as the plain scene does", "[scenes]") {
  const std::string plain = test::ReadFile(test::SourcePath("scenes/cgfs-transforms.json"));
  // As Notepad saves it: a UTF-8 byte-order mark first; and names as a person may capitalize them.
  const std::string text =
      "\xEF\xBB\xBF" +
      ReplaceAll(ReplaceAll(ReplaceAll(plain, "\"y\"", "\"Y\""), "\"red\"", "\"Red\""), "\"blue\"", "\"BLUE\"");
  REQUIRE(text.find("\"Y\"") != std::string::npos);
  REQUIRE(text.find("\"Red\"") != std::string::npos);
  const test::TempDir dir;
  test::WriteFile(dir / "notepad.json", text);
  const Scene expected = LoadScene(test::SourcePath("scenes/cgfs-transforms.json"));
  const Scene scene = LoadScene(dir / "notepad.json");
  REQUIRE(scene.camera.rotation == expected.camera.rotation);
  REQUIRE(scene.camera.rotation != glm::dmat3(1.0));  // the axis was read, and is y
  REQUIRE(scene.instances.size() == expected.instances.size());
  REQUIRE(scene.models.size() == expected.models.size());
  for (std::size_t i = 0; i < expected.models[0].triangles.size(); ++i) {
    INFO(i);
    REQUIRE(scene.models[0].triangles[i].colour == expected.models[0].triangles[i].colour);
  }
  // From memory too (standard input's path).
  REQUIRE(ParseScene(text, "<stdin>").camera.rotation == expected.camera.rotation);
}
