// `twinraster verify` and `render --verify` on a Vulkan device's image as a user runs them (built
// only with Vulkan): verdicts and exit codes, the map, the sentence about a difference, bad input
// that names the file and loses nothing, and SwiftShader's rules. What needs no device is in
// verify_cli_test.cpp.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/nothing_in_view.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>

using namespace twinraster;

namespace {

const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();

// Renders the scene on lavapipe into `dir`/gpu.png.
std::filesystem::path LavapipeImage(const test::TempDir& dir) {
  const test::CliResult r = test::RunCli({"render", kScene, "--backend", "gpu", "-o", (dir / "gpu.png").string()});
  REQUIRE(r.exit_code == 0);
  return dir / "gpu.png";
}

std::size_t CountRed(const Image& map) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < map.rgba.size(); i += 4)
    n += map.rgba[i] == 255 && map.rgba[i + 1] == 0 && map.rgba[i + 2] == 0;
  return n;
}

}  // namespace

TEST_CASE("verify: lavapipe's image passes (exit 0), and the map beside it is all grey and amber", "[cli][verify]") {
  const test::TempDir dir;
  const auto image = LavapipeImage(dir);
  const test::CliResult r = test::RunCli({"verify", kScene, image.string(), "--subpixel-bits", "8"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("passes: "));
  CHECK_THAT(r.out, HasSubstring(" 0 violations (subpixel bits 8, strict lines)"));
  const Image map = files::ReadPng((dir / "gpu-map.png").string());
  CHECK(map.width == 600);
  CHECK(CountRed(map) == 0);
}

TEST_CASE(
    "verify: an image upside down fails (exit 1), names the worst pixel and what is allowed there, and maps it red",
    "[cli][verify]") {
  const test::TempDir dir;
  Image image = files::ReadPng(LavapipeImage(dir).string());
  Image flipped(image.width, image.height);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    std::copy_n(image.pixel(0, y), image.width * 4, flipped.pixel(0, image.height - 1 - y));
  }
  files::WritePng((dir / "flipped.png").string(), flipped);
  const test::CliResult r = test::RunCli({"verify", kScene, (dir / "flipped.png").string(), "--json"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["format"] == "twinraster.verify/3");
  CHECK(j["passed"] == false);
  CHECK(j["pixels"]["violations"].get<int>() > 1000);
  CHECK(j["worst"]["allowed"].size() >= 1);
  CHECK(j["map"] == (dir / "flipped-map.png").string());
  CHECK(CountRed(files::ReadPng((dir / "flipped-map.png").string())) == j["pixels"]["violations"].get<std::size_t>());
  const test::CliResult text = test::RunCli({"verify", kScene, (dir / "flipped.png").string(), "--no-map"});
  CHECK_THAT(text.out, HasSubstring("fails: "));
  CHECK_THAT(text.out, HasSubstring(" allowed ("));
}

TEST_CASE("verify: bad input names the file and the problem, exits 2, and leaves an existing map alone",
          "[cli][verify]") {
  const test::TempDir dir;
  const auto map = dir / "map.png";
  test::WriteFile(map, "an earlier map");
  SECTION("an image of another size") {
    const test::CliResult r = test::RunCli({"verify", test::SourcePath("scenes/lookat.json").string(),
                                            LavapipeImage(dir).string(), "--map", map.string()});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, HasSubstring("gpu.png: the image is 600 x 600, but "));
    CHECK_THAT(r.err, HasSubstring("lookat.json draws a canvas of "));
  }
  SECTION("no such image") {
    const test::CliResult r = test::RunCli({"verify", kScene, (dir / "none.png").string(), "--map", map.string()});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, HasSubstring("none.png"));
  }
  SECTION("a scene that is not one") {
    test::WriteFile(dir / "bad.json", "{\"canvas\": 3}");
    const test::CliResult r =
        test::RunCli({"verify", (dir / "bad.json").string(), LavapipeImage(dir).string(), "--map", map.string()});
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, HasSubstring("bad.json"));
  }
  CHECK(test::ReadFile(map) == "an earlier map");
}

TEST_CASE("render --verify judges lavapipe's image and writes OUT-gpu-map.png, and --rules book refuses it",
          "[cli][verify][render]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kScene, "--verify", "-o", (dir / "t.png").string()});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("verify: gpu image passes: "));
  CHECK(std::filesystem::exists(dir / "t-gpu-map.png"));
  const test::CliResult book =
      test::RunCli({"render", kScene, "--verify", "--rules", "book", "-o", (dir / "b.png").string()});
  CHECK(book.exit_code == 2);
  CHECK_THAT(book.err, HasSubstring("--verify judges by Vulkan's rules"));
}

TEST_CASE("render --verify with both backends: identical images settle a scene with nothing in view (exit 0)",
          "[cli][verify][render]") {
  const test::TempDir dir;
  // A quad behind the camera: the verifier alone is inconclusive (exit 6, verify_cli_test.cpp),
  // but the device's image equal to the twin's, bit for bit, is the answer that decides.
  test::WriteFile(dir / "behind.json", test::kNothingInViewScene);
  const std::string scene = (dir / "behind.json").string(), out = (dir / "b.png").string();
  const test::CliResult r = test::RunCli({"render", scene, "--verify", "-o", out});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("gpu vs cpu: 64 x 48: 0 differing pixels"));
  CHECK_THAT(r.out, HasSubstring("verify: gpu image inconclusive: nothing is in view"));
  const test::CliResult gpu = test::RunCli({"render", scene, "--verify", "--backend", "gpu", "-o", out});
  CHECK(gpu.exit_code == 6);
  const test::CliResult json = test::RunCli({"render", scene, "--verify", "--json", "-o", out});
  const nlohmann::json j = nlohmann::json::parse(json.out);
  CHECK(j["verdict"] == "identical");
  CHECK(j["exit_code"] == 0);
  CHECK(j["verify"]["verdict"] == "inconclusive");
}

TEST_CASE(
    "render --backend both says what a difference is: within what Vulkan allows, but inconclusive (exit 6) where depth "
    "is uncertain",
    "[cli][verify][render]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli(
      {"render", test::SourcePath("scenes/hard/depth-ratio-1e-4.json").string(), "-o", (dir / "d.png").string()},
      {"GALLIUM_OVERRIDE_CPU_CAPS=nosse"});
  INFO(r.out << r.err);
  // The twin has no rules for the x87 path, so the verifier decides: no pixel is wrong, but in
  // float the two planes' depths cannot be told apart, so it cannot tell a broken image either.
  CHECK(r.exit_code == 6);
  CHECK_THAT(r.out, HasSubstring("verdict: the images differ in "));
  CHECK_THAT(r.out, HasSubstring(" px, all within what Vulkan allows"));
  CHECK_THAT(r.out, HasSubstring("but the judgement is inconclusive"));
}

TEST_CASE(
    "render --backend both on SwiftShader: the twin copies it bit for bit, the verifier judges at 4 bits, and verify "
    "reads the images' notes",
    "[cli][verify][render][swiftshader]") {
  const test::TempDir dir;
  const std::string scene = test::SourcePath("scenes/cgfs-transforms.json").string();
  const test::CliResult r = test::RunCli(
      {"render", scene, "--backend", "both", "--device", "swiftshader", "--verify", "-o", (dir / "ss.png").string()});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("(SwiftShader Device"));
  CHECK_THAT(r.out, HasSubstring("twin: SwiftShader rules, SwiftShader Device (Subzero), driver 5.0.0"));
  CHECK_THAT(r.out, HasSubstring("gpu vs cpu: 600 x 600: 0 differing pixels"));
  CHECK_THAT(r.out, HasSubstring("0 violations (subpixel bits 4, strict lines)"));
  // The twin's image says whose rules drew it: SwiftShader's 4 bits.
  const test::CliResult twin = test::RunCli({"verify", scene, (dir / "ss-cpu.png").string(), "--no-map"});
  INFO(twin.out << twin.err);
  CHECK(twin.exit_code == 0);
  CHECK_THAT(twin.out, HasSubstring("(subpixel bits 4, strict lines)"));
  // Judged later, by the rules the image carries: SwiftShader's 4 bits and strict lines.
  const test::CliResult v = test::RunCli({"verify", scene, (dir / "ss-gpu.png").string(), "--no-map"});
  INFO(v.out << v.err);
  CHECK(v.exit_code == 0);
  CHECK_THAT(v.out, HasSubstring("drawn by SwiftShader Device"));
  CHECK_THAT(v.out, HasSubstring("(subpixel bits 4, strict lines)"));
  // The same image judged as if from an unknown device: the loosest rules, still no violation.
  const test::CliResult loose =
      test::RunCli({"verify", scene, (dir / "ss-gpu.png").string(), "--no-map", "--strict-lines", "false"});
  CHECK(loose.exit_code == 0);
  CHECK_THAT(loose.out, HasSubstring("(subpixel bits 4)"));
}

TEST_CASE(
    "Version: --version lists every Vulkan device it reaches, SwiftShader and lavapipe, with the twin's rules for each",
    "[cli][swiftshader]") {
  const test::CliResult r = test::RunCli({"--version"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out,
             HasSubstring("SwiftShader Device (Subzero), driver 5.0.0, 4 subpixel bits, x86-64 SSE4.1 (proven on"));
  CHECK_THAT(r.out, HasSubstring("twin: bit-exact (SwiftShader rules, SwiftShader Device (Subzero)"));
  CHECK_THAT(r.out, HasSubstring("llvmpipe"));
  CHECK_THAT(r.out, HasSubstring("twin: bit-exact (lavapipe rules"));
}
