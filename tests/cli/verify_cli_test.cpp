// `twinraster verify` and `render --backend cpu --verify` as a user runs them, in a build with or
// without Vulkan: images without notes or with alpha, refused options, malformed and huge PNGs, and
// a scene with nothing in view. What judges a device's image is in verify_cli_device_test.cpp.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/nothing_in_view.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <algorithm>
#include <filesystem>
#include <string>

using namespace twinraster;

namespace {
const std::string kScene = test::SourcePath("scenes/cgfs-transforms.json").string();
}  // namespace

namespace {

// The twin's image of the scene, written again as another tool would: no PNG notes; with `alpha`
// in every pixel.
std::filesystem::path ResavedImage(const test::TempDir& dir, std::uint8_t alpha = 255) {
  const test::CliResult r = test::RunCli({"render", kScene, "--backend", "cpu", "-o", (dir / "twin.png").string()});
  REQUIRE(r.exit_code == 0);
  Image image = files::ReadPng(dir / "twin.png");
  for (std::size_t i = 3; i < image.rgba.size(); i += 4) image.rgba[i] = alpha;
  files::WritePng(dir / "resaved.png", image);
  return dir / "resaved.png";
}

}  // namespace

TEST_CASE("verify: an image without notes is judged by the spec's loosest rules, and the output says which it assumed",
          "[cli][verify]") {
  const test::TempDir dir;
  const std::string image = ResavedImage(dir).string();
  const test::CliResult r = test::RunCli({"verify", kScene, image, "--no-map"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring(image + ": its PNG notes do not say how the device rasterizes"));
  CHECK_THAT(r.out, HasSubstring("assumed the spec's loosest, subpixel bits 4 and non-strict lines; give the "
                                 "device's with --subpixel-bits N and --strict-lines true|false\n"));
  const auto j = nlohmann::json::parse(test::RunCli({"verify", kScene, image, "--no-map", "--json"}).out);
  CHECK(j["format"] == "twinraster.verify/3");
  CHECK(j["rules_from"] == nlohmann::json{{"subpixel_bits", "assumed"}, {"strict_lines", "assumed"}});
  // One rule given: only the other is assumed.
  const test::CliResult one = test::RunCli({"verify", kScene, image, "--no-map", "--subpixel-bits", "8"});
  CHECK_THAT(one.out, HasSubstring("assumed the spec's loosest, non-strict lines; give the device's with "
                                   "--strict-lines true|false\n"));
  // Both given, or the notes render writes: nothing is assumed, and nothing said.
  const test::CliResult both =
      test::RunCli({"verify", kScene, image, "--no-map", "--subpixel-bits", "8", "--strict-lines", "true"});
  CHECK(both.exit_code == 0);
  CHECK(both.out.find("assumed") == std::string::npos);
  const test::CliResult noted = test::RunCli({"verify", kScene, (dir / "twin.png").string(), "--no-map", "--json"});
  CHECK(nlohmann::json::parse(noted.out)["rules_from"] ==
        nlohmann::json{{"subpixel_bits", "notes"}, {"strict_lines", "notes"}});
  // --coverage judges by the same rules and says the same.
  const test::CliResult coverage = test::RunCli({"verify", kScene, image, "--no-map", "--coverage"});
  CHECK_THAT(coverage.out, HasSubstring("assumed the spec's loosest, subpixel bits 4 and non-strict lines"));
}

TEST_CASE("verify: alpha is not judged, and every verdict says how many pixels are not opaque", "[cli][verify]") {
  const test::TempDir dir;
  const std::string image = ResavedImage(dir, 0).string();
  // compare counts every pixel as differing from the opaque original...
  const test::CliResult c = test::RunCli({"compare", (dir / "twin.png").string(), image, "--json"});
  CHECK(nlohmann::json::parse(c.out)["differing_pixels"] == 360000);
  // ...where verify judges the colours alone, passes, and says so.
  const test::CliResult r = test::RunCli({"verify", kScene, image, "--no-map"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 0);
  CHECK_THAT(r.out, HasSubstring(image + ": alpha is not judged: 360000 of 360000 px are not opaque\n"));
  const auto j = nlohmann::json::parse(test::RunCli({"verify", kScene, image, "--no-map", "--json"}).out);
  CHECK(j["alpha"] == nlohmann::json{{"judged", false}, {"not_opaque", 360000}});
  const auto cj =
      nlohmann::json::parse(test::RunCli({"verify", kScene, image, "--no-map", "--coverage", "--json"}).out);
  CHECK(cj["format"] == "twinraster.verify-coverage/2");
  CHECK(cj["alpha"] == nlohmann::json{{"judged", false}, {"not_opaque", 360000}});
  const test::CliResult opaque = test::RunCli({"verify", kScene, (dir / "twin.png").string(), "--no-map"});
  CHECK_THAT(opaque.out, HasSubstring("alpha is not judged: 0 of 360000 px are not opaque\n"));
}

TEST_CASE("verify: --subpixel-bits below the spec's minimum, and --map with --no-map, are refused in one line (exit 2)",
          "[cli][verify]") {
  const test::TempDir dir;
  const auto map = dir / "map.png";
  test::WriteFile(map, "an earlier map");
  const std::string image = test::SourcePath("tests/files/pngs/valid/rgba8.png").string();
  const test::CliResult bits = test::RunCli({"verify", kScene, image, "--subpixel-bits", "3", "--map", map.string()});
  CHECK(bits.exit_code == 2);
  CHECK_THAT(bits.err, HasSubstring("twinraster verify: --subpixel-bits: Vulkan requires subPixelPrecisionBits of at "
                                    "least 4 (the spec's Required Limits), got 3\n"));
  const test::CliResult both = test::RunCli({"verify", kScene, image, "--map", map.string(), "--no-map"});
  CHECK(both.exit_code == 2);
  CHECK_THAT(both.err, HasSubstring("twinraster verify: --map " + map.string() +
                                    " writes the map and --no-map writes none: give one of them\n"));
  CHECK(test::ReadFile(map) == "an earlier map");
}

TEST_CASE("verify and compare: every malformed PNG exits 2, naming the file, with no control character from it",
          "[cli][verify][png]") {
  const test::TempDir dir;
  const std::string scene = test::SourcePath("scenes/cgfs-transforms.json").string();
  const std::string good = test::SourcePath("tests/files/pngs/valid/rgba8.png").string();
  const auto printable = [](const std::string& text) {
    return std::none_of(text.begin(), text.end(),
                        [](char c) { return (static_cast<unsigned char>(c) < 0x20 && c != '\n') || c == 0x7f; });
  };
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::SourcePath("tests/files/pngs/malformed"))) {
    const std::string png = entry.path().string();
    INFO(png);
    const test::CliResult v = test::RunCli({"verify", scene, png, "--map", (dir / "map.png").string()});
    INFO(v.out << v.err);
    CHECK(v.exit_code == 2);
    CHECK_THAT(v.err, HasSubstring(png + ": "));
    CHECK(printable(v.out + v.err));
    const test::CliResult c = test::RunCli({"compare", good, png});
    INFO(c.out << c.err);
    CHECK(c.exit_code == 2);
    CHECK_THAT(c.err, HasSubstring(png + ": cannot read as PNG: "));
    CHECK(printable(c.out + c.err));
    ++files;
  }
  CHECK(files == 26);  // tests/files/pngs/README.md lists them
  CHECK_FALSE(std::filesystem::exists(dir / "map.png"));
  // The bomb's size is refused against the scene's canvas before a pixel is decoded: had it been
  // decoded, the message would be the cut-off IDAT's.
  const test::CliResult bomb =
      test::RunCli({"verify", scene, test::SourcePath("tests/files/pngs/malformed/bomb-16384-truncated.png").string()});
  CHECK_THAT(bomb.err, HasSubstring("the image is 16384 x 16384, but"));
}

TEST_CASE("compare: a valid PNG that declares 16384 x 16384 pixels is read a row at a time, in little memory",
          "[cli][compare][png]") {
  const std::string big = test::SourcePath("tests/files/pngs/large/declares-16384x16384.png").string();
  const std::string small = test::SourcePath("tests/files/pngs/valid/rgba8.png").string();
  const test::TempDir dir;
  const std::string diff = (dir / "d.png").string();
  test::WriteFile(diff, "an earlier diff");
  // Both headers are read before either file is decoded: a diff it would need 1 GiB for is refused at once.
  const test::CliResult refused = test::RunCli({"compare", big, big, "--diff", diff});
  CHECK(refused.exit_code == 2);
  CHECK_THAT(refused.err, HasSubstring("--diff " + diff +
                                       ": a diff image is drawn whole, for at most 33554432 pixels, and these are "
                                       "16384 x 16384: compare them without --diff\n"));
  CHECK(test::ReadFile(diff) == "an earlier diff");
  // Of another size, it is still read through (a corrupt file is refused whatever its size).
  const test::CliResult r = test::RunCli({"compare", big, small, "--json"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["a"]["width"] == 16384);
  CHECK(j["same_size"] == false);
  // The largest child's peak memory (CTest runs each case in a process of its own): a few rows,
  // where holding the image would take 1 GiB (2.1 GB before, with both held).
  rusage usage{};
  REQUIRE(getrusage(RUSAGE_CHILDREN, &usage) == 0);
  CHECK(usage.ru_maxrss < 256 * 1024);  // KiB
}

TEST_CASE("A scene with nothing in view: render --verify and verify say so, and stay inconclusive (exit 6)",
          "[cli][verify]") {
  const test::TempDir dir;
  // A quad behind the camera: nothing may cover any pixel, so the right image is empty.
  test::WriteFile(dir / "behind.json", test::kNothingInViewScene);
  const std::string said =
      "inconclusive: nothing is in view (no triangle may cover any pixel), so an empty image is both the right "
      "answer and what a broken renderer draws; all 3072 px are the background, 0 violations";
  const auto image = dir / "b.png";
  const test::CliResult render =
      test::RunCli({"render", (dir / "behind.json").string(), "--backend", "cpu", "--verify", "-o", image.string()});
  INFO(render.err);
  REQUIRE(render.exit_code == 6);
  REQUIRE(render.out.find("verify: cpu image " + said) != std::string::npos);
  REQUIRE(render.out.find("of the 0 covered") == std::string::npos);
  const test::CliResult verify = test::RunCli({"verify", (dir / "behind.json").string(), image.string()});
  REQUIRE(verify.exit_code == 6);
  REQUIRE(verify.out.find(image.string() + ": " + said) != std::string::npos);
  const test::CliResult coverage =
      test::RunCli({"verify", "--coverage", (dir / "behind.json").string(), image.string()});
  REQUIRE(coverage.exit_code == 6);
  REQUIRE(coverage.out.find("; nothing is in view (no triangle may cover any pixel), so an image with nothing covered "
                            "is both the right answer and what a broken engine draws") != std::string::npos);
}
