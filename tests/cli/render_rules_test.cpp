// `render --rules book` as a user runs it: the demo's canvas on the CPU without any Vulkan device,
// outputs named as --backend cpu names them, JSON saying which rules drew, and scenes the book's
// rules cannot draw reported like bad scenes.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <string>

using namespace twinraster;

namespace {

const std::string kFigure2 = test::SourcePath("scenes/cgfs-scene.json").string();
const std::string kFigure10 = test::SourcePath("scenes/cgfs-transforms.json").string();
const std::string kNoVulkan = "VK_ICD_FILENAMES=/nonexistent/icd.json";  // no driver at all

}  // namespace

TEST_CASE(
    "render --rules book draws the demo's canvas on the CPU, with no Vulkan device, named as --backend cpu names it",
    "[cli][render][book]") {
  const test::TempDir dir;
  const test::CliResult r =
      test::RunCli({"render", kFigure2, "--rules", "book", "-o", (dir / "f.png").string(), "--json"}, {kNoVulkan});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["rules"] == "book");
  REQUIRE(j["instances"] == 1);
  REQUIRE(j["triangles"] == 12);
  REQUIRE(j["backends"]["gpu"].is_null());
  REQUIRE(j["backends"]["cpu"]["output"] == (dir / "f.png").string());
  REQUIRE(j["backends"]["cpu"]["device"] == "book rules: the chapter's demos, 1 thread");
  REQUIRE(j["differing_pixels"].is_null());
  // Figure 10-2's wireframe: 2509 painted pixels on the demo page's canvas (tests/book).
  const Image image = files::ReadPng(dir / "f.png");
  REQUIRE(image.width == 600);
  REQUIRE(test::CountNotColour(image, {255, 255, 255}) == 2509);
  REQUIRE(std::distance(std::filesystem::directory_iterator(dir.path()), {}) == 1);

  // --backend cpu said outright is the same; the text report names the rules.
  const test::CliResult text =
      test::RunCli({"render", kFigure2, "--rules", "book", "--backend", "cpu", "-o", (dir / "g.png").string()});
  REQUIRE(text.exit_code == 0);
  REQUIRE(text.out.find("cpu: " + (dir / "g.png").string() + "  (book rules: the chapter's demos, 1 thread)") !=
          std::string::npos);
  REQUIRE(files::ReadPng(dir / "g.png").rgba == image.rgba);

  // Several scenes into a directory: one PNG each, named after the scene, no -cpu suffix.
  const auto out = dir / "figures";
  const test::CliResult many = test::RunCli({"render", kFigure2, kFigure10, "--rules", "book", "-o", out.string()});
  INFO(many.err);
  REQUIRE(many.exit_code == 0);
  REQUIRE(files::ReadPng(out / "cgfs-scene.png").rgba == image.rgba);
  REQUIRE(test::CountNotColour(files::ReadPng(out / "cgfs-transforms.png"), {255, 255, 255}) == 5648);
  REQUIRE(std::distance(std::filesystem::directory_iterator(out), {}) == 2);

  // -o - is one PNG on standard output.
  const test::CliResult piped = test::RunCli({"render", kFigure2, "--rules", "book", "-o", "-"});
  REQUIRE(piped.exit_code == 0);
  test::WriteFile(dir / "piped.png", piped.out);
  REQUIRE(files::ReadPng(dir / "piped.png").rgba == image.rgba);
}

TEST_CASE(
    "render --rules book reports a scene the demos cannot draw like a bad scene: exit 2, and the others still render",
    "[cli][render][book]") {
  const test::TempDir dir;
  std::string odd = test::ReadFile(kFigure2);
  const std::string width = "\"width\": 600";
  odd.replace(odd.find(width), width.size(), "\"width\": 601");
  const test::CliResult r =
      test::RunCliWithInput({"render", "-", "--rules", "book", "-o", (dir / "odd.png").string()}, odd);
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.out.empty());
  REQUIRE(r.err.rfind("twinraster: <stdin>: canvas: --rules book: the book's rules need an even width and height (this "
                      "canvas is 601 x 600)",
                      0) == 0);
  REQUIRE_FALSE(std::filesystem::exists(dir / "odd.png"));
  // The same scene under the Vulkan rules draws.
  REQUIRE(test::RunCliWithInput({"render", "-", "--backend", "cpu", "-o", (dir / "odd.png").string()}, odd).exit_code ==
          0);

  test::WriteFile(dir / "odd.json", odd);
  const auto out = dir / "frames";
  const test::CliResult many =
      test::RunCli({"render", (dir / "odd.json").string(), kFigure2, "--rules", "book", "-o", out.string()});
  REQUIRE(many.exit_code == 2);
  REQUIRE(many.err.find("odd.json: canvas: --rules book: ") != std::string::npos);
  REQUIRE(test::CountNotColour(files::ReadPng(out / "cgfs-scene.png"), {255, 255, 255}) == 2509);
  REQUIRE_FALSE(std::filesystem::exists(out / "odd.png"));
}
