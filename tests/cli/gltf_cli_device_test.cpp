// glTF files drawn on a Vulkan device as a user meets them (built only with Vulkan): COLOR_0
// interpolated alike by lavapipe and the twin, render, explain and verify taking a file with the
// same --camera and --size, a scene file placing a glTF file as a model, and each shipped glTF scene
// (scenes/gltf/) drawn alike and passed by --verify. What needs no device is in gltf_cli_test.cpp.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/gltf_bytes.hpp"
#include "support/image_counts.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

const std::string kModels = "/usr/share/assimp/models/glTF2/";
const std::string kCameras = kModels + "cameras/Cameras.gltf";

// A quad (a fan of two triangles) with a colour per vertex (COLOR_0, floats), in front of a
// perspective camera; `unlit` adds KHR_materials_unlit, else it is lit flat (no normals).
std::string ColouredQuad(bool unlit) {
  const float data[] = {-1, -1, 0, 1, -1, 0, 1, 1, 0, -1, 1, 0,      // positions
                        1,  0,  0, 0, 1,  0, 0, 0, 1, 1,  1, 0.2f};  // COLOR_0, linear RGB
  const auto* raw = reinterpret_cast<const std::uint8_t*>(data);
  const std::string base64 = test::Base64(std::vector<std::uint8_t>(raw, raw + sizeof data));
  return std::string(R"({"asset":{"version":"2.0"},)") + (unlit ? R"("extensionsUsed":["KHR_materials_unlit"],)" : "") +
         R"("buffers":[{"byteLength":96,"uri":"data:application/octet-stream;base64,)" + base64 + R"("}],
  "bufferViews":[{"buffer":0,"byteLength":48},{"buffer":0,"byteOffset":48,"byteLength":48}],
  "accessors":[{"bufferView":0,"componentType":5126,"count":4,"type":"VEC3"},
               {"bufferView":1,"componentType":5126,"count":4,"type":"VEC3"}],
  "materials":[{"pbrMetallicRoughness":{"baseColorFactor":[1,1,1,1]})" +
         (unlit ? R"(,"extensions":{"KHR_materials_unlit":{}})" : "") + R"(}],
  "meshes":[{"primitives":[{"attributes":{"POSITION":0,"COLOR_0":1},"material":0,"mode":6}]}],
  "cameras":[{"type":"perspective","perspective":{"yfov":0.9,"aspectRatio":1.5,"znear":0.1,"zfar":10}}],
  "nodes":[{"mesh":0,"rotation":[0,0.2,0,0.98]},{"camera":0,"translation":[0.2,0.1,3]}],
  "scenes":[{"nodes":[0,1]}]})";
}

}  // namespace

TEST_CASE("A glTF file's COLOR_0 is interpolated across each triangle: lavapipe == twin, and verify passes",
          "[cli][gltf]") {
  const test::TempDir dir;
  for (const bool unlit : {true, false}) {
    INFO((unlit ? "unlit" : "lit flat"));
    test::WriteFile(dir / "quad.gltf", ColouredQuad(unlit));
    const test::CliResult r = test::RunCli(
        {"render", (dir / "quad.gltf").string(), "--verify", "--size", "240x160", "-o", (dir / "q.png").string()});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    CHECK(r.out.find("0 differing pixels") != std::string::npos);
    CHECK(r.out.find("verify: gpu image passes") != std::string::npos);
    // The colours vary across the quad: many more than its four corners'.
    const Image image = files::ReadPng(dir / "q-cpu.png");
    CHECK(test::DistinctColours(image) > (unlit ? 1000u : 4u));
  }
}

TEST_CASE("render, explain and verify take a glTF file with the same --camera and --size", "[cli][gltf]") {
  const test::TempDir dir;
  const std::string out = (dir / "cam.png").string();
  const test::CliResult r = test::RunCli({"render", kCameras, "--camera", "1", "--size", "320x200", "-o", out});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("320 x 200") != std::string::npos);
  CHECK(r.out.find("0 differing pixels") != std::string::npos);
  CHECK(files::ReadPng(dir / "cam-gpu.png").width == 320);

  const test::CliResult v =
      test::RunCli({"verify", kCameras, (dir / "cam-gpu.png").string(), "--camera", "1", "--size", "320x200"});
  INFO(v.out << v.err);
  CHECK(v.exit_code == 0);
  // Judged against another camera, the same image is wrong.
  const test::CliResult wrong = test::RunCli(
      {"verify", kCameras, (dir / "cam-gpu.png").string(), "--camera", "0", "--size", "320x200", "--no-map"});
  CHECK(wrong.exit_code == 1);

  const test::CliResult e = test::RunCli({"explain", kCameras, "--camera", "1", "--size", "320x200"});
  INFO(e.err);
  REQUIRE(e.exit_code == 0);
  CHECK(e.out.find("canvas Cw x Ch = 320 x 200 px") != std::string::npos);
  CHECK(e.out.find("orthographic") != std::string::npos);
  CHECK(e.out.find("a glTF node chain of") != std::string::npos);
  CHECK(e.out.find("the chapter's mirror") != std::string::npos);
}

TEST_CASE("A scene file places a glTF file as a model, and --size widens any scene's view", "[cli][gltf]") {
  const test::TempDir dir;
  test::WriteFile(dir / "scene.json", R"({
    "canvas": {"width": 200, "height": 200},
    "viewport": {"width": 1, "height": 1, "distance": 1},
    "camera": {"position": [0, 0, -4]},
    "lighting": {"ambient": 0.2, "lights": [{"type": "directional", "direction": [0, 0, -1], "intensity": 0.8}]},
    "models": {"cube": {"gltf": ")" + kModels +
                                          R"(glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf"}},
    "instances": [{"model": "cube", "transform": {"scale": 10}}, {"model": "cube", "transform": {"translation": [1, 0, 0], "scale": 5}}]
  })");
  const test::CliResult r =
      test::RunCli({"render", (dir / "scene.json").string(), "--size", "300x200", "-o", (dir / "s.png").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.find("2 instances, 24 triangles, 300 x 200") != std::string::npos);
  CHECK(r.out.find("0 differing pixels") != std::string::npos);
  const test::CliResult e = test::RunCli({"explain", (dir / "scene.json").string(), "--size", "300x200"});
  CHECK(e.out.find("viewport Vw x Vh = 1.5 x 1 at distance d = 1") != std::string::npos);
}

TEST_CASE("glTF scenes: render draws each shipped glTF scene on lavapipe as the twin does, and verify passes it",
          "[cli][gltf]") {
  const test::TempDir dir;
  std::size_t judged = 0;
  for (const char* file : {"scenes/gltf/arm.gltf", "scenes/gltf/strips.gltf", "scenes/gltf/colonnade.glb"}) {
    const test::CliResult r = test::RunCli(
        {"render", test::SourcePath(file).string(), "-o", (dir / "out.png").string(), "--verify", "--json"});
    INFO(file << "\n" << r.out << r.err);
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    CHECK(j["differing_pixels"] == 0);
    CHECK(j["backends"]["gpu"]["status"] == "rendered");
    CHECK(j["verify"]["verdict"] == "passed");
    CHECK(j["width"].get<int>() != j["height"].get<int>());  // the glTF camera's aspect ratio, not 1
    ++judged;
  }
  CHECK(judged == 3);
}
