// `twinraster render` on the twin alone, or refused before it draws, and `compare`, as a user runs
// them in a build with or without Vulkan: outputs, JSON, exit codes, and output files that a failed
// run never truncates or destroys. What draws on a device is in render_cli_device_test.cpp.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace twinraster;

namespace {
const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();
}  // namespace

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
  test::WriteFile(dir / "plain", "a file where a directory should be");
  const auto out = dir / "plain" / "x.png";
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
  files::WritePng(dir / "a.png", a);
  files::WritePng(dir / "a2.png", a);
  files::WritePng(dir / "b.png", b);
  REQUIRE(test::RunCli({"compare", (dir / "a.png").string(), (dir / "a2.png").string()}).exit_code == 0);
  const test::CliResult r = test::RunCli(
      {"compare", (dir / "a.png").string(), (dir / "b.png").string(), "--diff", (dir / "d.png").string(), "--json"});
  REQUIRE(r.exit_code == 1);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["format"] == "twinraster.compare/1");
  REQUIRE(j["a"]["file"] == (dir / "a.png").string());
  REQUIRE(j["b"]["width"] == 4);
  REQUIRE(j["b"]["height"] == 3);
  REQUIRE(j["same_size"] == true);
  REQUIRE(j["identical"] == false);
  REQUIRE(j["differing_pixels"] == 1);
  REQUIRE(j["max_channel_difference"] == 9);
  REQUIRE(j["diff"] == (dir / "d.png").string());
  const Image diff = files::ReadPng(dir / "d.png");
  REQUIRE(diff.pixel(2, 1)[0] == 255);
  REQUIRE(diff.pixel(2, 1)[1] == 0);
  test::WriteFile(dir / "not.png", "text");
  const test::CliResult bad = test::RunCli({"compare", (dir / "a.png").string(), (dir / "not.png").string()});
  REQUIRE(bad.exit_code == 2);
  REQUIRE(bad.err.find("not.png") != std::string::npos);

  // Sizes that differ: no pixel counts (null, not missing), no diff, exit 1.
  files::WritePng(dir / "small.png", Image(2, 2));
  const test::CliResult sizes =
      test::RunCli({"compare", (dir / "a.png").string(), (dir / "small.png").string(), "--json"});
  REQUIRE(sizes.exit_code == 1);
  const auto s = nlohmann::json::parse(sizes.out);
  REQUIRE(s["same_size"] == false);
  REQUIRE(s["identical"] == false);
  REQUIRE(s.contains("differing_pixels"));
  REQUIRE(s["differing_pixels"].is_null());
  REQUIRE(s["max_channel_difference"].is_null());
  REQUIRE(s["diff"].is_null());
}

TEST_CASE("render --json keeps every key with one backend: the other backend and the comparison are null",
          "[cli][render]") {
  const test::TempDir dir;
  const test::CliResult r =
      test::RunCli({"render", kScene, "-o", (dir / "c.png").string(), "--backend", "cpu", "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"format", "scene", "verdict", "exit_code", "reason", "rules", "wireframe", "width", "height",
                          "instances", "triangles", "load_ms", "differing_pixels", "max_channel_difference", "diff",
                          "backends", "twin_rules", "verify"}) {
    INFO(key);
    REQUIRE(j.contains(key));
  }
  REQUIRE(j.size() == 18);
  REQUIRE(j["verdict"] == "rendered");
  REQUIRE(j["verify"].is_null());  // not asked for, and nothing differs
  REQUIRE(j["rules"] == "vulkan");
  REQUIRE(j["wireframe"] == false);
  REQUIRE(j["instances"] == 2);
  REQUIRE(j["triangles"] == 24);
  REQUIRE(j["differing_pixels"].is_null());
  REQUIRE(j["max_channel_difference"].is_null());
  REQUIRE(j["diff"].is_null());
  REQUIRE(j["backends"].size() == 2);
  REQUIRE(j["backends"]["gpu"].is_null());
  REQUIRE(j["backends"]["cpu"]["output"] == (dir / "c.png").string());
  REQUIRE(j["backends"]["cpu"]["device"].get<std::string>().rfind("CPU twin, ", 0) == 0);
}

TEST_CASE("render reads SCENE - from standard input and writes -o - as PNG bytes to standard output", "[cli][render]") {
  const std::string scene_text = test::ReadFile(kScene);
  const test::TempDir dir;
  const test::CliResult r = test::RunCliWithInput({"render", "-", "-o", "-", "--backend", "cpu"}, scene_text);
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  // Standard output is the PNG and nothing else; the report went to standard error.
  REQUIRE(r.out.rfind("\x89PNG\r\n\x1a\n", 0) == 0);
  test::WriteFile(dir / "out.png", r.out);
  const Image image = files::ReadPng(dir / "out.png");
  REQUIRE(image.width == 600);
  REQUIRE(image.height == 600);
  REQUIRE(r.err.rfind("-: 2 instances, 24 triangles, 600 x 600, loaded in ", 0) == 0);
  REQUIRE(r.err.find("\ncpu: standard output  (CPU twin, ") != std::string::npos);

  // The same image as a file written from the scene file.
  REQUIRE(test::RunCli({"render", kScene, "-o", (dir / "file.png").string(), "--backend", "cpu"}).exit_code == 0);
  REQUIRE(files::ReadPng(dir / "file.png").rgba == image.rgba);

  // --quiet: nothing at all on standard error.
  const test::CliResult quiet = test::RunCliWithInput({"render", "-", "-o", "-", "--backend", "cpu", "-q"}, scene_text);
  REQUIRE(quiet.exit_code == 0);
  REQUIRE(quiet.err.empty());
  REQUIRE(quiet.out == r.out);

  // A bad scene on standard input is named <stdin>.
  const test::CliResult bad = test::RunCliWithInput({"render", "-", "-o", (dir / "bad.png").string()}, "{\"canvas\": ");
  REQUIRE(bad.exit_code == 2);
  REQUIRE(bad.err.rfind("twinraster: <stdin>: line ", 0) == 0);
  REQUIRE(!std::filesystem::exists(dir / "bad.png"));
}

TEST_CASE("Standard streams are refused where they cannot work, before anything is drawn or written", "[cli][render]") {
  const test::TempDir dir;
  struct Case {
    std::vector<std::string> args;
    std::string says;
  };
  const std::vector<Case> cases = {
      {{"render", kScene, "-o", "-"}, "--backend both makes two"},
      {{"render", kScene, "-o", "-", "--backend", "cpu", "--json"}, "-o - and --json both want standard output"},
      {{"render", "-", "--backend", "cpu"}, "SCENE - (standard input) needs -o OUT.png"},
  };
  for (const Case& c : cases) {
    const test::CliResult r = test::RunCliWithInput(c.args, test::ReadFile(kScene));
    INFO(r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.out.empty());
    REQUIRE(r.err.rfind("twinraster render: ", 0) == 0);
    REQUIRE(r.err.find(c.says) != std::string::npos);
    REQUIRE(std::count(r.err.begin(), r.err.end(), '\n') == 2);  // the problem, then the hint
  }
}

TEST_CASE("render -o and compare --diff must name .png files, in any case", "[cli][render][compare]") {
  const test::TempDir dir;
  test::WriteFile(dir / "keep.jpg", "earlier result");
  for (const std::string name : {"keep.jpg", "frame", "frame.png.tmp", ".png"}) {
    INFO(name);
    const test::CliResult r = test::RunCli({"render", kScene, "-o", (dir / name).string(), "--backend", "cpu"});
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.err.find("the output must be a file name ending in .png") != std::string::npos);
  }
  REQUIRE(test::ReadFile(dir / "keep.jpg") == "earlier result");
  REQUIRE(std::distance(std::filesystem::directory_iterator(dir.path()), {}) == 1);

  const test::CliResult upper =
      test::RunCli({"render", kScene, "-o", (dir / "Frame.PNG").string(), "--backend", "cpu"});
  INFO(upper.err);
  REQUIRE(upper.exit_code == 0);
  REQUIRE(files::ReadPng(dir / "Frame.PNG").width == 600);

  Image a(2, 2), b(2, 2);
  b.pixel(0, 0)[0] = 200;
  files::WritePng(dir / "a.png", a);
  files::WritePng(dir / "b.png", b);
  const test::CliResult diff =
      test::RunCli({"compare", (dir / "a.png").string(), (dir / "b.png").string(), "--diff", (dir / "d.gif").string()});
  REQUIRE(diff.exit_code == 2);
  REQUIRE(diff.err.find("--diff") != std::string::npos);
  REQUIRE(!std::filesystem::exists(dir / "d.gif"));
}
