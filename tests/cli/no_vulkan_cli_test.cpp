// A build configured with -DTWINRASTER_VULKAN=OFF, as its user meets it (built only there): what
// needs a device exits 3 with one line saying that this build has no Vulkan, --version says so,
// and render --backend cpu draws as in any build.
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <filesystem>
#include <string>

using namespace twinraster;

namespace {

const std::string kTransforms = test::SourcePath("scenes/cgfs-transforms.json").string();
const std::string kNoVulkan =
    "twinraster: this build has no Vulkan: it was configured with -DTWINRASTER_VULKAN=OFF; render --backend cpu "
    "draws without it\n";

}  // namespace

TEST_CASE("No Vulkan: render on the GPU or on both exits 3 with one line and writes no image", "[cli][no-vulkan]") {
  for (const char* backend : {"gpu", "both"}) {
    const test::TempDir dir;
    const test::CliResult r =
        test::RunCli({"render", kTransforms, "--backend", backend, "-o", (dir / "f.png").string()});
    INFO(backend << "\n" << r.out << r.err);
    CHECK(r.exit_code == 3);
    CHECK(r.err == kNoVulkan);
    CHECK_FALSE(std::filesystem::exists(dir / "f.png"));
    CHECK_FALSE(std::filesystem::exists(dir / "f-gpu.png"));
  }
  // both is the default backend.
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kTransforms, "-q", "-o", (dir / "f.png").string()});
  CHECK(r.exit_code == 3);
  CHECK(r.err == kNoVulkan);
}

TEST_CASE("No Vulkan: render --backend cpu draws the twin's image", "[cli][no-vulkan]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli({"render", kTransforms, "--backend", "cpu", "-o", (dir / "f.png").string()});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK(std::filesystem::file_size(dir / "f.png") > 0);
}

TEST_CASE("No Vulkan: --version says that this build has no Vulkan", "[cli][no-vulkan]") {
  const test::CliResult r = test::RunCli({"--version"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK(r.out.find("none reachable (this build has no Vulkan: it was configured with -DTWINRASTER_VULKAN=OFF)") !=
        std::string::npos);
}

TEST_CASE("No Vulkan: bench's GPU rows and --scale exit 3 with the line, its CPU rows run", "[cli][no-vulkan]") {
  const std::string scenes = test::SourcePath("scenes").string();
  const test::CliResult gpu =
      test::RunCli({"bench", "--only", "cgfs-transforms", "--runs", "1", "--scenes", scenes, "-q"});
  CHECK(gpu.exit_code == 3);
  CHECK(gpu.err == kNoVulkan);
  const test::CliResult scale = test::RunCli({"bench", "--scale", "--counts", "1", "--runs", "1", "-q"});
  CHECK(scale.exit_code == 3);
  CHECK(scale.err == kNoVulkan);
  const test::CliResult cpu = test::RunCli({"bench", "--only", "cgfs-transforms", "--runs", "1", "--scenes", scenes,
                                            "--methods", "compose-f64,cpu-twin", "-q"});
  INFO(cpu.out << cpu.err);
  CHECK(cpu.exit_code == 0);
  CHECK(cpu.out.find("cpu-twin") != std::string::npos);
}
