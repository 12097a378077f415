// `render --backend cpu --device` as a user types it, opening no device, in a build with or without
// Vulkan: the twin's rules chosen by the name, and refused when it has none; and --threads' help
// saying what the twin does. The names devices answer to are in device_names_cli_device_test.cpp.
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <filesystem>
#include <fstream>
#include <string>

using namespace twinraster;

namespace {

const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();
const std::string kNoVulkan = "VK_ICD_FILENAMES=/nonexistent/icd.json";  // no driver at all

std::string ReadFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), {}};
}

}  // namespace

TEST_CASE("render --backend cpu --device lavapipe says its release is assumed from the name", "[cli][render][device]") {
  const test::TempDir dir;
  const test::CliResult r = test::RunCli(
      {"render", kScene, "--backend", "cpu", "--device", "lavapipe", "-o", (dir / "c.png").string()}, {kNoVulkan});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("twin: lavapipe rules, Mesa 22.3.6 (assumed: 'lavapipe' asked, no device opened)"));
  const test::CliResult none =
      test::RunCli({"render", kScene, "--backend", "cpu", "-o", (dir / "d.png").string()}, {kNoVulkan});
  CHECK_THAT(none.out, HasSubstring("(assumed: no device was asked)"));
}

TEST_CASE(
    "render --backend cpu --device with a name the twin has no rules for is refused, exit 2, one line, nothing "
    "written",
    "[cli][render][device]") {
  const test::TempDir dir;
  const auto out = dir / "keep.png";
  std::ofstream(out) << "an earlier image";
  for (const char* name : {"nvidia", "SwiftShader Device (LLVM)", "gpu"}) {
    INFO(name);
    const test::CliResult r =
        test::RunCli({"render", kScene, "--backend", "cpu", "--device", name, "-o", out.string()}, {kNoVulkan});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, HasSubstring("twinraster render: --device '" + std::string(name) +
                                   "': with no device opened (--backend cpu) the twin takes its rules from the "
                                   "name alone, and knows lavapipe"));
    CHECK(r.out.empty());
    CHECK(ReadFile(out) == "an earlier image");
  }
  const test::CliResult gpu =
      test::RunCli({"render", kScene, "--backend", "cpu", "--device", "gpu", "-o", out.string()}, {kNoVulkan});
  CHECK_THAT(gpu.err, HasSubstring("gpu is a backend, not a device"));

  // The book's rules follow no device.
  const test::CliResult book =
      test::RunCli({"render", kScene, "--rules", "book", "--device", "lavapipe", "-o", out.string()}, {kNoVulkan});
  INFO(book.err);
  CHECK(book.exit_code == 2);
  CHECK_THAT(book.err, HasSubstring("--device chooses Vulkan's rules, and --rules book draws by the demos'"));
  CHECK(ReadFile(out) == "an earlier image");
}

TEST_CASE("render --help says when the twin's default draws on one thread and when on every core",
          "[cli][render][threads]") {
  const test::CliResult r = test::RunCli({"render", "--help"});
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("the CPU twin's threads, at most one per 16 rows (default: every core for a"));
  CHECK_THAT(r.out, HasSubstring("frame of over 1048576 pixels or over 4096 triangles"));
  CHECK_THAT(r.out, !HasSubstring("default: all cores"));
}
