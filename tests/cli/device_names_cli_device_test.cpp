// `render --device` as a user types it, on the devices a build with Vulkan reaches (built only
// there): the names the manual uses, any case, any part of a device's name; a name no device
// answers to, listed against the names that work; and the twin drawing by SwiftShader's rules as
// SwiftShader draws. What opens no device is in device_names_cli_test.cpp.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

using namespace twinraster;

namespace {

const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();
const std::string kNoVulkan = "VK_ICD_FILENAMES=/nonexistent/icd.json";  // no driver at all

}  // namespace

TEST_CASE("render --device takes the manual's names in any case, and any part of a device's name",
          "[cli][render][device]") {
  const test::TempDir dir;
  for (const char* name : {"lavapipe", "LavaPipe", "llvmpipe", "LLVM "}) {
    INFO(name);
    const test::CliResult r =
        test::RunCli({"render", kScene, "--backend", "gpu", "--device", name, "-o", (dir / "l.png").string()});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, HasSubstring("  (llvmpipe (LLVM "));
  }
  for (const char* name : {"swiftshader", "SWIFTSHADER", "subzero"}) {
    INFO(name);
    const test::CliResult r =
        test::RunCli({"render", kScene, "--backend", "gpu", "--device", name, "-o", (dir / "s.png").string()});
    INFO(r.out << r.err);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, HasSubstring("  (SwiftShader Device (Subzero))"));
  }
}

TEST_CASE("render --device with a name no device answers to lists the devices by the names they answer to",
          "[cli][render][device]") {
  const test::TempDir dir;
  const test::CliResult r =
      test::RunCli({"render", kScene, "--device", "no such device", "-o", (dir / "n.png").string()});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 3);
  CHECK_THAT(r.err, HasSubstring("no usable Vulkan device: --device 'no such device' matches none (a device "
                                 "answers to its common name or to any part of its full name, in any case); the "
                                 "devices here: "));
  CHECK_THAT(r.err, HasSubstring("lavapipe (llvmpipe (LLVM "));
  CHECK_THAT(r.err, HasSubstring("swiftshader (SwiftShader Device (Subzero))"));
  CHECK_THAT(r.err, !HasSubstring("is a backend"));
  CHECK(std::filesystem::is_empty(dir.path()));

  // A backend typed as a device is told what it is.
  const test::CliResult gpu = test::RunCli({"render", kScene, "--device", "gpu", "-o", (dir / "g.png").string()});
  INFO(gpu.err);
  CHECK(gpu.exit_code == 3);
  CHECK_THAT(gpu.err, HasSubstring("gpu is a backend, not a device: --backend gpu draws on Vulkan alone"));
  const test::CliResult cpu = test::RunCli({"render", kScene, "--device", "CPU", "-o", (dir / "c.png").string()});
  INFO(cpu.err);
  CHECK(cpu.exit_code == 3);
  CHECK_THAT(cpu.err, HasSubstring("CPU is a backend, not a device: --backend cpu draws on the CPU twin alone"));
}

TEST_CASE("Version: --version lists each Vulkan device by the name --device takes", "[cli][device]") {
  const test::CliResult r = test::RunCli({"--version"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("Vulkan devices, by the names --device takes"));
  CHECK_THAT(r.out, HasSubstring("\n  lavapipe (llvmpipe (LLVM "));
  CHECK_THAT(r.out, HasSubstring("\n  swiftshader (SwiftShader Device (Subzero)): "));
}

TEST_CASE(
    "render --backend cpu --device swiftshader draws by SwiftShader's rules with no Vulkan at all, as SwiftShader "
    "draws, and says the name chose them",
    "[cli][render][device][swiftshader]") {
  const test::TempDir dir;
  const test::CliResult both =
      test::RunCli({"render", kScene, "--backend", "both", "--device", "swiftshader", "-o", (dir / "b.png").string()});
  INFO(both.out << both.err);
  REQUIRE(both.exit_code == 0);
  const test::CliResult r = test::RunCli(
      {"render", kScene, "--backend", "cpu", "--device", "swiftshader", "-o", (dir / "c.png").string()}, {kNoVulkan});
  INFO(r.out << r.err);
  REQUIRE(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring("twin: SwiftShader rules ('swiftshader' asked, no device opened), SwiftShader "
                                 "Device (Subzero), driver 5.0.0, 4 subpixel bits"));
  CHECK_THAT(r.out, !HasSubstring("no device was asked"));
  CHECK(files::ReadPng(dir / "c.png").rgba == files::ReadPng(dir / "b-gpu.png").rgba);
  CHECK(files::ReadPng(dir / "c.png").rgba == files::ReadPng(dir / "b-cpu.png").rgba);

  // The JSON says whose rules, and the image's notes carry SwiftShader's 4 subpixel bits to verify.
  const test::CliResult j = test::RunCli(
      {"render", kScene, "--backend", "cpu", "--device", "SwiftShader", "-o", (dir / "j.png").string(), "--json"},
      {kNoVulkan});
  REQUIRE(j.exit_code == 0);
  const auto json = nlohmann::json::parse(j.out);
  CHECK(json["twin_rules"]["rasterizer"] == "swiftshader");
  CHECK(json["twin_rules"]["exact"] == true);
  CHECK_THAT(json["twin_rules"]["text"].get<std::string>(), HasSubstring("('SwiftShader' asked, no device opened)"));
  const test::CliResult v = test::RunCli({"verify", kScene, (dir / "j.png").string(), "--no-map"});
  INFO(v.out << v.err);
  CHECK(v.exit_code == 0);
  CHECK_THAT(v.out, HasSubstring("(subpixel bits 4, strict lines)"));
}
