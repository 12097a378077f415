// `render` when the Vulkan driver crashes or hangs, as a user meets it: the report names the
// crash or the time limit and the scene, the twin's image is still written, a batch goes on to its
// later scenes, and exit code 5 tells a script what happened.
#include "files/png_file.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

using namespace twinraster;

namespace {

const std::string kTransforms = test::SourcePath("scenes/cgfs-transforms.json").string();
const std::string kLookAt = test::SourcePath("scenes/lookat.json").string();
const std::string kDegenerate = test::SourcePath("scenes/hard/degenerate.json").string();

}  // namespace

TEST_CASE("render: a Vulkan driver that aborts is reported, and the twin's image is still written",
          "[cli][render][isolation]") {
  const test::TempDir dir;
  const std::string out = (dir / "f.png").string();
  const test::CliResult r = test::RunCli({"render", kTransforms, "-o", out}, {"TWINRASTER_TEST_GPU_FAULT=abort"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 5);
  CHECK(r.out.find("gpu: the Vulkan driver crashed (SIGABRT) on " + kTransforms + "; no gpu image") !=
        std::string::npos);
  CHECK(r.out.find("gpu vs cpu: not compared, there is no gpu image") != std::string::npos);
  CHECK(r.out.find("twin: ") != std::string::npos);
  CHECK_FALSE(std::filesystem::exists(dir / "f-gpu.png"));
  const Image cpu = files::ReadPng((dir / "f-cpu.png").string());
  CHECK(cpu.width == 600);
}

TEST_CASE("render: a Vulkan driver that hangs is stopped by --timeout and reported", "[cli][render][isolation]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kTransforms, "-o", (dir / "f.png").string(), "--timeout", "1"},
                                         {"TWINRASTER_TEST_GPU_FAULT=hang"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 5);
  CHECK(r.out.find("gpu: timed out after 1 s on " + kTransforms + "; no gpu image") != std::string::npos);
  CHECK(std::filesystem::exists(dir / "f-cpu.png"));
}

TEST_CASE("render: a batch goes on after the Vulkan driver crashes, each scene in a fresh GPU process",
          "[cli][render][isolation]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kTransforms, kLookAt, "-o", dir.path().string(), "--json"},
                                         {"TWINRASTER_TEST_GPU_FAULT=abort"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 5);
  int scenes = 0;
  for (std::size_t at = 0; at < r.out.size();) {
    const std::size_t end = r.out.find('\n', at);
    const auto j = nlohmann::json::parse(r.out.substr(at, end - at));
    CHECK(j["backends"]["gpu"]["status"] == "crashed");
    CHECK(j["backends"]["cpu"]["status"] == "rendered");
    CHECK(std::filesystem::exists(j["backends"]["cpu"]["output"].get<std::string>()));
    ++scenes;
    at = end + 1;
  }
  CHECK(scenes == 2);
}

// lavapipe at 128-bit vectors corrupts its heap on these scenes (docs/mesa-128bit-crash.md), but not
// on every machine or every run: on one 2-core machine Mesa 22.3.6 died every time, on CI's machine
// not at all. So the test does not need the crash; the fake drivers above make it happen for sure.
// Whichever scene kills the driver, if any, the twin's image of each is written, the batch goes on in
// a fresh child, and the exit code says whether one crashed.
TEST_CASE("render: lavapipe's own crash at 128-bit vectors costs one scene its GPU image, not the batch",
          "[cli][render][isolation]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kDegenerate, kTransforms, "-o", dir.path().string(), "--json"},
                                         {"LP_NATIVE_VECTOR_WIDTH=128"});
  INFO(r.out << r.err);
  const auto first = nlohmann::json::parse(r.out.substr(0, r.out.find('\n')));
  const auto second = nlohmann::json::parse(r.out.substr(r.out.find('\n') + 1));
  CHECK(std::filesystem::exists(dir / "degenerate-cpu.png"));
  CHECK(std::filesystem::exists(dir / "cgfs-transforms-cpu.png"));
  bool crashed = false;
  for (const auto* run : {&first, &second}) {
    const std::string status = (*run)["backends"]["gpu"]["status"];
    CHECK((status == "rendered" || status == "crashed"));
    crashed = crashed || status == "crashed";
  }
  CHECK(std::filesystem::exists(dir / "cgfs-transforms-gpu.png") ==
        (second["backends"]["gpu"]["status"] == "rendered"));
  CHECK(r.exit_code == (crashed ? 5 : 0));
}
