// The shipped glTF scenes (scenes/gltf/) through `verify --coverage` as a user runs it, in a build
// with or without Vulkan: it passes the twin's image recoloured as an engine's shading would (with
// its own clear colour), and fails the image of a file with a transform defect (a field of view 1 %
// wide, a child not under its parent), recoloured the same way. gltf_cli_device_test.cpp draws the
// scenes on lavapipe.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

using namespace twinraster;

namespace {

const Rgb8 kGltfClear{40, 40, 48};  // what every glTF scene clears to (scene/gltf_scene.cpp)
const Rgb8 kMagenta{255, 0, 255};

bool Is(const std::uint8_t* p, Rgb8 c) { return p[0] == c.r && p[1] == c.g && p[2] == c.b; }

// An engine's image of `twin`: covered pixels in random colours (never magenta), the clear magenta.
std::filesystem::path Engine(const std::filesystem::path& twin, const std::filesystem::path& out) {
  Image image = files::ReadPng(twin);
  std::mt19937 random(5);
  std::size_t covered = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    std::uint8_t* p = &image.rgba[i];
    if (Is(p, kGltfClear)) {
      p[0] = kMagenta.r, p[1] = kMagenta.g, p[2] = kMagenta.b;
      continue;
    }
    for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(random() & 255);
    if (Is(p, kMagenta)) p[0] ^= 1;
    ++covered;
  }
  REQUIRE(covered > 1000);
  files::WritePng(out, image);
  return out;
}

test::CliResult CoverageOf(const std::filesystem::path& scene, const std::filesystem::path& image) {
  return test::RunCli(
      {"verify", "--coverage", scene.string(), image.string(), "--background", "#ff00ff", "--json", "--no-map"});
}

}  // namespace

TEST_CASE("verify --coverage: a glTF scene's image recoloured by an engine passes, a defect's image fails",
          "[cli][verify][coverage][gltf]") {
  const test::TempDir dir;
  const std::filesystem::path scene = test::SourcePath("scenes/gltf/arm.gltf");
  REQUIRE(
      test::RunCli({"render", scene.string(), "--backend", "cpu", "-q", "-o", (dir / "twin.png").string()}).exit_code ==
      0);
  const test::CliResult good = CoverageOf(scene, Engine(dir / "twin.png", dir / "engine.png"));
  INFO(good.out << good.err);
  CHECK(good.exit_code == 0);
  CHECK(nlohmann::json::parse(good.out)["verdict"] == "passed");

  // The defects written into a copy of the file, drawn by the twin and recoloured the same way.
  const nlohmann::json original = nlohmann::json::parse(std::ifstream(scene));
  nlohmann::json wide = original, detached = original;
  wide["cameras"][0]["perspective"]["yfov"] = original["cameras"][0]["perspective"]["yfov"].get<double>() * 1.01;
  // The forearm (the elbow's child) made a root: its local matrix drawn as its world.
  nlohmann::json& elbow = detached["nodes"][4];
  REQUIRE(elbow["name"] == "elbow");
  const nlohmann::json forearm = elbow["children"][0];
  REQUIRE(detached["nodes"][forearm.get<std::size_t>()]["name"] == "forearm");
  elbow.erase("children");
  detached["scenes"][0]["nodes"].push_back(forearm);
  std::size_t failed = 0;
  for (const auto& [name, doc] : {std::pair{"wide", wide}, std::pair{"detached", detached}}) {
    const std::filesystem::path file = dir / (std::string(name) + ".gltf");
    std::ofstream(file) << doc.dump();
    const std::filesystem::path twin = dir / (std::string(name) + ".png");
    REQUIRE(test::RunCli({"render", file.string(), "--backend", "cpu", "-q", "-o", twin.string()}).exit_code == 0);
    const test::CliResult bad = CoverageOf(scene, Engine(twin, dir / (std::string(name) + "-engine.png")));
    INFO(name << "\n" << bad.out << bad.err);
    CHECK(bad.exit_code == 1);
    const auto j = nlohmann::json::parse(bad.out);
    CHECK(j["verdict"] == "failed");
    CHECK(j["pixels"]["violations"].get<std::uint64_t>() > 0);
    failed += bad.exit_code == 1;
  }
  CHECK(failed == 2);
}
