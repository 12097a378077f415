// `twinraster render` and `compare` as a user runs them: outputs, JSON, exit codes, and output
// files that a failed run never truncates or destroys.
#include "image/image.hpp"
#include "image/png_file.hpp"
#include "support/test_support.hpp"

#include <catch2/catch.hpp>
#include <nlohmann/json.hpp>

#include <filesystem>

using namespace twinraster;

namespace {
const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();
// The Vulkan loader finds no driver at all with this: how a machine without lavapipe looks.
const std::string kNoVulkan = "VK_ICD_FILENAMES=/nonexistent/icd.json";
}  // namespace

TEST_CASE("render --backend both writes both PNGs, reports 0 differing pixels, exits 0", "[cli][render]") {
  const test::TempDir dir;
  const auto out = dir / "frame.png";
  const test::CliResult r = test::RunCli({"render", kScene, "-o", out.string(), "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["width"] == 600);
  REQUIRE(j["height"] == 600);
  REQUIRE(j["differing_pixels"] == 0);
  REQUIRE(j["max_channel_difference"] == 0);
  for (const char* backend : {"gpu", "cpu"}) {
    const auto& b = j["backends"][backend];
    for (const char* stage : {"setup", "draw", "readback", "png"}) REQUIRE(b["timings_ms"][stage].get<double>() >= 0);
    const Image image = ReadPng(b["output"].get<std::string>());
    REQUIRE(image.width == 600);
  }
  REQUIRE(std::filesystem::exists(dir / "frame-gpu.png"));
  REQUIRE(std::filesystem::exists(dir / "frame-cpu.png"));
  REQUIRE(!std::filesystem::exists(dir / "frame-diff.png"));
  // Nothing but the two outputs (no diff: the images agree), and no temporary left behind.
  REQUIRE(std::distance(std::filesystem::directory_iterator(dir.path()), {}) == 2);
}

TEST_CASE("Without a Vulkan device: gpu exits 3 saying what to install, cpu still works", "[cli][render]") {
  const test::TempDir dir;
  const test::CliResult gpu = test::RunCli({"render", kScene, "-o", (dir / "g.png").string(), "--backend", "gpu"}, {kNoVulkan});
  REQUIRE(gpu.exit_code == 3);
  REQUIRE(gpu.err.find("apt-get install mesa-vulkan-drivers") != std::string::npos);
  REQUIRE(!std::filesystem::exists(dir / "g.png"));
  const test::CliResult cpu = test::RunCli({"render", kScene, "-o", (dir / "c.png").string(), "--backend", "cpu"}, {kNoVulkan});
  INFO(cpu.err);
  REQUIRE(cpu.exit_code == 0);
  REQUIRE(ReadPng(dir / "c.png").height == 600);
}

TEST_CASE("A failed render leaves an existing output untouched", "[cli][render]") {
  const test::TempDir dir;
  const auto out = dir / "keep.png";
  test::WriteFile(out, "earlier result");
  const auto bad_scene = dir / "bad.json";
  test::WriteFile(bad_scene, "{\"canvas\": ");
  const test::CliResult r = test::RunCli({"render", bad_scene.string(), "-o", out.string(), "--backend", "cpu"});
  REQUIRE(r.exit_code == 2);
  REQUIRE(test::ReadFile(out) == "earlier result");
  REQUIRE(std::distance(std::filesystem::directory_iterator(dir.path()), {}) == 2);
}

TEST_CASE("An output that cannot be written is reported with its name and exit code 2", "[cli][render]") {
  const test::TempDir dir;
  const auto out = dir / "no-such-dir" / "x.png";
  const test::CliResult r = test::RunCli({"render", kScene, "-o", out.string(), "--backend", "cpu"});
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find(out.string()) != std::string::npos);
  const test::CliResult usage = test::RunCli({"render", kScene, "--backend", "both-ish"});
  REQUIRE(usage.exit_code == 2);
}

TEST_CASE("compare: identical images exit 0, different ones exit 1 with a diff", "[cli][compare]") {
  const test::TempDir dir;
  Image a(4, 3);
  for (std::size_t i = 0; i < a.rgba.size(); ++i) a.rgba[i] = std::uint8_t(i * 7);
  Image b = a;
  b.pixel(2, 1)[1] = std::uint8_t(b.pixel(2, 1)[1] + 9);
  WritePng(dir / "a.png", a);
  WritePng(dir / "a2.png", a);
  WritePng(dir / "b.png", b);
  REQUIRE(test::RunCli({"compare", (dir / "a.png").string(), (dir / "a2.png").string()}).exit_code == 0);
  const test::CliResult r = test::RunCli(
      {"compare", (dir / "a.png").string(), (dir / "b.png").string(), "--diff", (dir / "d.png").string(), "--json"});
  REQUIRE(r.exit_code == 1);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["differing_pixels"] == 1);
  REQUIRE(j["max_channel_difference"] == 9);
  const Image diff = ReadPng(dir / "d.png");
  REQUIRE(diff.pixel(2, 1)[0] == 255);
  REQUIRE(diff.pixel(2, 1)[1] == 0);
  test::WriteFile(dir / "not.png", "text");
  const test::CliResult bad = test::RunCli({"compare", (dir / "a.png").string(), (dir / "not.png").string()});
  REQUIRE(bad.exit_code == 2);
  REQUIRE(bad.err.find("not.png") != std::string::npos);
}

TEST_CASE("render -o must name a file, and an output that is a directory fails before anything is replaced", "[cli][render]") {
  const test::TempDir dir;
  REQUIRE(test::RunCli({"render", kScene, "-o", dir.path().string(), "--backend", "cpu"}).exit_code == 2);
  REQUIRE(test::RunCli({"render", kScene, "-o", dir.path().string() + "/", "--backend", "cpu"}).exit_code == 2);
  REQUIRE(test::RunCli({"render", kScene, "-o", "", "--backend", "cpu"}).exit_code == 2);

  // x-gpu.png holds an earlier result; x-cpu.png is in the way as a directory. The run must fail
  // without touching x-gpu.png, although the GPU image was rendered and staged first.
  test::WriteFile(dir / "x-gpu.png", "earlier result");
  std::filesystem::create_directory(dir / "x-cpu.png");
  const test::CliResult r = test::RunCli({"render", kScene, "-o", (dir / "x.png").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err.find("x-cpu.png") != std::string::npos);
  REQUIRE(test::ReadFile(dir / "x-gpu.png") == "earlier result");
  REQUIRE(std::distance(std::filesystem::directory_iterator(dir.path()), {}) == 2);  // no temporary left
}

TEST_CASE("Without a Vulkan device, bench exits 3 too", "[cli][bench]") {
  const test::CliResult r = test::RunCli({"bench", "--runs", "1", "--only", "cgfs-scene", "--scenes",
                                          test::SourcePath("scenes").string()}, {kNoVulkan});
  REQUIRE(r.exit_code == 3);
  REQUIRE(r.err.find("mesa-vulkan-drivers") != std::string::npos);
}
