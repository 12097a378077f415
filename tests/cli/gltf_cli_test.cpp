// glTF files on the command line where no device is needed, in a build with or without Vulkan: what
// a file holds that is not drawn is a note, and choosing a camera, a scene or a size wrongly, or a
// hostile file, is one line and exit code 2 that leaves an existing output as it was. What draws on
// a device is in gltf_cli_device_test.cpp.
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <algorithm>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

const std::string kModels = "/usr/share/assimp/models/glTF2/";
const std::string kCameras = kModels + "cameras/Cameras.gltf";
const std::string kMorph = kModels + "glTF-Sample-Models/AnimatedMorphCube-glTF/AnimatedMorphCube.gltf";

}  // namespace

TEST_CASE("What a glTF file holds that is not drawn is one note line each on standard error", "[cli][gltf]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kMorph, "--backend", "cpu", "-o", (dir / "m.png").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.find("note: " + kMorph + ": 1 primitive with morph targets: drawn without them\n") != std::string::npos);
  CHECK(r.err.find("note: " + kMorph + ": 1 animation: drawn at rest\n") != std::string::npos);
  const test::CliResult quiet =
      test::RunCli({"render", kMorph, "--backend", "cpu", "-q", "-o", (dir / "q.png").string()});
  CHECK(quiet.err.empty());
}

TEST_CASE("Choosing a camera, a scene or a size wrongly is one line and exit code 2", "[cli][gltf][bad-input]") {
  const test::TempDir dir;
  const std::string out = (dir / "x.png").string();
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"render", kCameras, "--camera", "nope", "-o", out},
       "--camera nope names no camera; the file's cameras: camera 0, camera 1"},
      {{"render", kCameras, "--scene", "4", "-o", out}, "--scene 4: the file has 1 scene: give 0"},
      {{"render", test::SourcePath("scenes/lookat.json").string(), "--camera", "0", "-o", out},
       "--camera 0: only a glTF file has cameras to choose"},
      {{"render", kCameras, "--size", "0x10", "-o", out}, "--size \"0x10\": expected WxH"},
      {{"explain", kCameras, "--size", "20000x10"}, "--size \"20000x10\": expected WxH"},
      {{"verify", kCameras, out, "--size", "abc"}, "--size \"abc\": expected WxH"},
  };
  for (const Case& c : cases) {
    const test::CliResult r = test::RunCli(c.args);
    INFO(c.args[0] << " " << c.says);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find(c.says) != std::string::npos);
  }
}

TEST_CASE("A hostile glTF file is refused with the file and the place, and an existing output is kept",
          "[cli][gltf][bad-input]") {
  const test::TempDir dir;
  const std::string out = (dir / "golden.png").string();
  test::WriteFile(out, "not touched");
  struct Case {
    std::string file, text, says;
  };
  const std::vector<Case> cases = {
      {"cycle.gltf", R"({"asset":{"version":"2.0"},"nodes":[{"children":[1]},{"children":[0]}]})",
       "nodes: node 0 is its own ancestor"},
      {"escape.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"../../etc/passwd"}]})",
       "buffers[0].uri: the URI \"../../etc/passwd\" is refused: it leaves the model's folder"},
      {"scheme.gltf", R"({"asset":{"version":"2.0"},"buffers":[{"byteLength":4,"uri":"http://example.com/a.bin"}]})",
       "it has a scheme"},
      {"old.gltf", R"({"asset":{"version":"1.0"}})", "asset.version: glTF \"1.0\": twinraster reads glTF 2.0 only"},
      {"broken.gltf", R"({"asset":{"version":"2.0"},)", "line 1"},
      {"short.glb", std::string("glTF\x02\0\0\0", 8), "byte 0: a .glb shorter than its headers"},
  };
  for (const Case& c : cases) {
    test::WriteFile(dir / c.file, c.text);
    const test::CliResult r = test::RunCli({"render", (dir / c.file).string(), "-o", out});
    INFO(c.file << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK(r.err.find((dir / c.file).string() + ": ") != std::string::npos);
    CHECK(r.err.find(c.says) != std::string::npos);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(test::ReadFile(out) == "not touched");
  }
}
