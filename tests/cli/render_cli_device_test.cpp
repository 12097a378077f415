// `twinraster render` on a Vulkan device as a user runs it (built only with Vulkan): both backends'
// outputs and JSON, a machine with no driver, progress, several scenes in one run, and wireframes.
// What needs no device is in render_cli_test.cpp.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

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
  REQUIRE(j["format"] == "twinraster.render/5");
  REQUIRE(j["scene"] == kScene);
  REQUIRE(j["verdict"] == "identical");
  REQUIRE(j["exit_code"] == 0);
  REQUIRE(j["reason"] == "0 differing pixels");
  REQUIRE(j["width"] == 600);
  REQUIRE(j["height"] == 600);
  REQUIRE(j["differing_pixels"] == 0);
  REQUIRE(j["max_channel_difference"] == 0);
  REQUIRE(j["diff"].is_null());
  for (const char* backend : {"gpu", "cpu"}) {
    const auto& b = j["backends"][backend];
    for (const char* stage : {"setup", "draw", "readback", "png"}) REQUIRE(b["timings_ms"][stage].get<double>() >= 0);
    const Image image = files::ReadPng(b["output"].get<std::string>());
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
  const test::CliResult gpu =
      test::RunCli({"render", kScene, "-o", (dir / "g.png").string(), "--backend", "gpu"}, {kNoVulkan});
  REQUIRE(gpu.exit_code == 3);
  REQUIRE(gpu.err.find("apt-get install mesa-vulkan-drivers") != std::string::npos);
  REQUIRE(!std::filesystem::exists(dir / "g.png"));
  const test::CliResult cpu =
      test::RunCli({"render", kScene, "-o", (dir / "c.png").string(), "--backend", "cpu"}, {kNoVulkan});
  INFO(cpu.err);
  REQUIRE(cpu.exit_code == 0);
  REQUIRE(files::ReadPng(dir / "c.png").height == 600);
}

TEST_CASE(
    "render -o must name a file or a directory, and an output that is a directory fails before anything is "
    "replaced",
    "[cli][render]") {
  const test::TempDir dir;
  REQUIRE(test::RunCli({"render", kScene, "-o", "", "--backend", "cpu"}).exit_code == 2);
  REQUIRE(test::RunCli({"render", kScene, "-o", (dir / "frame").string(), "--backend", "cpu"}).exit_code == 2);

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
  const test::CliResult r = test::RunCli(
      {"bench", "--runs", "1", "--only", "cgfs-scene", "--scenes", test::SourcePath("scenes").string()}, {kNoVulkan});
  REQUIRE(r.exit_code == 3);
  REQUIRE(r.err.find("mesa-vulkan-drivers") != std::string::npos);
}

TEST_CASE("Without a terminal on standard error, render and bench print no progress", "[cli][progress]") {
  const test::TempDir dir;
  const test::CliResult render = test::RunCli({"render", kScene, "-o", (dir / "x.png").string()});
  INFO(render.err);
  REQUIRE(render.exit_code == 0);
  REQUIRE(render.err.empty());
  REQUIRE(render.out.find("drawing") == std::string::npos);
  const test::CliResult bench = test::RunCli({"bench", "--runs", "1", "--only", "cgfs-scene", "--methods",
                                              "compose-f64,cpu-twin", "--scenes", test::SourcePath("scenes").string()});
  INFO(bench.err);
  REQUIRE(bench.exit_code == 0);
  REQUIRE(bench.err.empty());
  REQUIRE(bench.out.find("[1/") == std::string::npos);
}

TEST_CASE("On a terminal, render and bench show progress on standard error, and --quiet silences it",
          "[cli][progress]") {
  const test::TempDir dir;
  const std::vector<std::string> render = {"render", kScene, "-o", (dir / "x.png").string()};
  const std::vector<std::string> bench = {"bench",
                                          "--runs",
                                          "1",
                                          "--only",
                                          "cgfs-scene",
                                          "--methods",
                                          "compose-f64,cpu-twin",
                                          "--scenes",
                                          test::SourcePath("scenes").string(),
                                          "--json"};
  const test::CliResult shown = test::RunCliInTerminal(render);
  INFO(shown.out + shown.err);
  REQUIRE(shown.exit_code == 0);
  for (const char* stage : {"gpu: drawing on Vulkan...", "cpu: drawing...", "writing the PNGs..."}) {
    INFO(stage);
    REQUIRE(shown.out.find(stage) != std::string::npos);
  }
  REQUIRE(shown.out.find("\r\033[K") != std::string::npos);  // each stage replaces the last, then is erased

  auto quiet = render;
  quiet.push_back("--quiet");
  const test::CliResult silent = test::RunCliInTerminal(quiet);
  REQUIRE(silent.exit_code == 0);
  REQUIRE(silent.out.find("drawing") == std::string::npos);
  REQUIRE(silent.out.find("\033[K") == std::string::npos);
  REQUIRE(silent.out.find("gpu vs cpu: 600 x 600: 0 differing pixels") != std::string::npos);

  const test::CliResult rows = test::RunCliInTerminal(bench);
  REQUIRE(rows.exit_code == 0);
  // compose-f64, then the twin with one thread and (on a machine with more) with every core.
  REQUIRE(rows.out.find("[1/") != std::string::npos);
  REQUIRE(rows.out.find("] cgfs-scene compose-f64, ") != std::string::npos);
  REQUIRE(rows.out.find("] cgfs-scene cpu-twin, 1 thread: frame ") != std::string::npos);
  auto bench_quiet = bench;
  bench_quiet.push_back("-q");
  const test::CliResult no_rows = test::RunCliInTerminal(bench_quiet);
  REQUIRE(no_rows.exit_code == 0);
  REQUIRE(no_rows.out.find("[1/") == std::string::npos);
  REQUIRE(no_rows.out.find("\"format\": \"twinraster.bench/2\"") != std::string::npos);
}

TEST_CASE("render with several scenes writes each into -o DIR, keeps going past a bad one, exits with the worst code",
          "[cli][render][many]") {
  const test::TempDir dir;
  const std::string lookat = test::SourcePath("scenes/lookat.json").string();
  test::WriteFile(dir / "broken.json", "{\"canvas\": ");
  const auto out = dir / "frames";  // made by render
  const test::CliResult r =
      test::RunCli({"render", kScene, (dir / "broken.json").string(), lookat, "-o", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 2);  // the worst: the broken scene's bad input, although the others matched
  REQUIRE(r.err.find("broken.json: line 1") != std::string::npos);
  for (const char* file : {"cgfs-transforms-gpu.png", "cgfs-transforms-cpu.png", "lookat-gpu.png", "lookat-cpu.png"}) {
    INFO(file);
    REQUIRE(files::ReadPng(out / file).width > 0);
  }
  REQUIRE_FALSE(std::filesystem::exists(out / "broken-gpu.png"));
  // The Vulkan device is made once: the second scene's set-up is only its buffers.
  REQUIRE(r.out.find("lookat.json: 3 instances, 36 triangles, 640 x 480") != std::string::npos);

  const test::CliResult good =
      test::RunCli({"render", kScene, lookat, "-o", out.string(), "--backend", "cpu", "--png-level", "9"});
  REQUIRE(good.exit_code == 0);
  REQUIRE(files::ReadPng(out / "lookat.png").width == 640);
  // One scene that cannot be read, with --json: its object says so, as a batch's line would.
  const test::CliResult alone = test::RunCli(
      {"render", (dir / "broken.json").string(), "-o", out.string() + "/b.png", "--backend", "cpu", "--json"});
  REQUIRE(alone.exit_code == 2);
  REQUIRE(alone.err ==
          "twinraster: " + (dir / "broken.json").string() + ": line 1, column 12: " +
              "syntax error while parsing value - unexpected end of input; expected '[', '{', or a literal\n");
  const auto j = nlohmann::json::parse(alone.out);
  REQUIRE(j["verdict"] == "error");
  REQUIRE(j["exit_code"] == 2);
  REQUIRE(j["width"].is_null());
  REQUIRE(j["backends"]["cpu"].is_null());
  REQUIRE_FALSE(std::filesystem::exists(out / "b.png"));
  // -o naming a file, and - among several scenes, are refused before anything runs.
  test::WriteFile(dir / "plain.txt", "x");
  REQUIRE(test::RunCli({"render", kScene, lookat, "-o", (dir / "plain.txt").string()}).exit_code == 2);
  REQUIRE(test::RunCli({"render", kScene, "-", "-o", out.string()}).exit_code == 2);
}

TEST_CASE("render with several scenes: records in the order given, each scene's files written while the next draws",
          "[cli][render][many]") {
  const test::TempDir dir;
  const std::string lookat = test::SourcePath("scenes/lookat.json").string();
  test::WriteFile(dir / "broken.json", "{\"canvas\": ");
  std::filesystem::copy_file(lookat, dir / "again.json");
  const std::vector<std::string> scenes = {kScene, (dir / "broken.json").string(), lookat,
                                           (dir / "again.json").string()};
  std::vector<std::string> args = {"render"};
  args.insert(args.end(), scenes.begin(), scenes.end());
  for (const std::string& extra :
       std::vector<std::string>{"-o", (dir / "out").string(), "--json", "--junit", (dir / "j.xml").string()}) {
    args.push_back(extra);
  }
  const test::CliResult r = test::RunCli(args);
  INFO(r.err);
  REQUIRE(r.exit_code == 2);
  // One JSON line per scene, in order, the broken one's too, each with its verdict and exit code;
  // the twin, drawn while the GPU process drew the later scenes, matches it.
  std::vector<std::string> printed;
  std::istringstream lines(r.out);
  for (std::string line; std::getline(lines, line);) {
    const auto j = nlohmann::json::parse(line);
    printed.push_back(j["scene"]);
    INFO(line);
    const bool broken = j["scene"] == scenes[1];
    CHECK(j["verdict"] == (broken ? "error" : "identical"));
    CHECK(j["exit_code"] == (broken ? 2 : 0));
    CHECK(j["differing_pixels"] == (broken ? nlohmann::json(nullptr) : nlohmann::json(0)));
    if (broken) CHECK(j["reason"].get<std::string>().rfind(scenes[1] + ": line 1, column ", 0) == 0);
  }
  REQUIRE(printed == scenes);
  // The JUnit file has every scene, the broken one in its place, with the verdict JSON gave it.
  REQUIRE(test::ReadFile(dir / "j.xml").find("<error type=\"error\" message=\"" + scenes[1] + ": line 1") !=
          std::string::npos);
  const std::string xml = test::ReadFile(dir / "j.xml");
  std::size_t at = 0;
  for (const std::string& scene : scenes) {
    INFO(scene);
    at = xml.find("name=\"" + scene + "\"", at);
    REQUIRE(at != std::string::npos);
  }
  // A batch's images are the ones a scene drawn on its own gets.
  const test::CliResult alone = test::RunCli({"render", lookat, "-o", (dir / "alone.png").string()});
  REQUIRE(alone.exit_code == 0);
  CHECK(files::ReadPng(dir / "out/again-gpu.png").rgba == files::ReadPng(dir / "alone-gpu.png").rgba);
  CHECK(files::ReadPng(dir / "out/again-cpu.png").rgba == files::ReadPng(dir / "alone-cpu.png").rgba);
}

TEST_CASE("render --wireframe: both backends draw the edges, identically, and the report says so",
          "[cli][render][wireframe]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kScene, "--wireframe", "-o", (dir / "w.png").string(), "--json"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["wireframe"] == true);
  REQUIRE(j["differing_pixels"] == 0);
  // Edges only: far fewer pixels differ from the background than in the filled image.
  const test::CliResult filled = test::RunCli({"render", kScene, "--backend", "cpu", "-o", (dir / "f.png").string()});
  REQUIRE(filled.exit_code == 0);
  const test::CliResult compared =
      test::RunCli({"compare", (dir / "w-cpu.png").string(), (dir / "f.png").string(), "--json"});
  REQUIRE(compared.exit_code == 1);
  REQUIRE(nlohmann::json::parse(compared.out)["differing_pixels"].get<std::uint64_t>() > 10000);
}
