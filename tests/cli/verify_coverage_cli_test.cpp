// `twinraster verify --coverage` as a user runs it: an engine's image with its own shading and
// clear colour passes (exit 0), a transform bug fails (exit 1) with its pixels in the map's own
// colours, a judgement that cannot tell is inconclusive (exit 6), and a malformed --background or
// --hole-tolerance is a usage error (exit 2) that writes nothing.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <filesystem>
#include <fstream>
#include <random>
#include <string>

using namespace twinraster;

namespace {

const std::string kScene = test::SourcePath("scenes/lookat.json").string();
const Rgb8 kSceneClear{40, 40, 48};  // lookat.json's background
const Rgb8 kMagenta{255, 0, 255};

std::filesystem::path TwinImage(const test::TempDir& dir, const std::string& scene, const std::string& name) {
  const test::CliResult r = test::RunCli({"render", scene, "--backend", "cpu", "-q", "-o", (dir / name).string()});
  REQUIRE(r.exit_code == 0);
  return dir / name;
}

bool Is(const std::uint8_t* p, Rgb8 c) { return p[0] == c.r && p[1] == c.g && p[2] == c.b; }

// An engine's image: the twin's covered pixels in random colours (never `clear`), its background
// `clear`, written without notes (judged at the spec's loosest rules).
std::filesystem::path Engine(const std::filesystem::path& twin, Rgb8 clear, const std::filesystem::path& out) {
  Image image = files::ReadPng(twin);
  std::mt19937 random(3);
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    std::uint8_t* p = &image.rgba[i];
    if (Is(p, kSceneClear)) {
      p[0] = clear.r, p[1] = clear.g, p[2] = clear.b;
      continue;
    }
    for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(random() & 255);
    if (Is(p, clear)) p[0] ^= 1;
  }
  files::WritePng(out, image);
  return out;
}

std::size_t Count(const Image& map, Rgb8 colour) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < map.rgba.size(); i += 4) n += Is(&map.rgba[i], colour);
  return n;
}

}  // namespace

TEST_CASE("verify --coverage: an engine's own shading and clear colour pass (exit 0), judged at 4 subpixel bits",
          "[cli][verify][coverage]") {
  const test::TempDir dir;
  const auto engine = Engine(TwinImage(dir, kScene, "twin.png"), kMagenta, dir / "engine.png");
  for (const char* colour : {"255,0,255", "255, 0, 255", "#ff00FF"}) {
    const test::CliResult r = test::RunCli({"verify", "--coverage", kScene, engine.string(), "--background", colour});
    INFO(colour << "\n" << r.out << r.err);
    CHECK(r.exit_code == 0);
    CHECK_THAT(r.out, HasSubstring("coverage passes: "));
    CHECK_THAT(r.out, HasSubstring(" 0 px covered where no primitive may reach, 0 px of the clear colour (255, 0, "
                                   "255) (--background)"));
    CHECK_THAT(r.out, HasSubstring("(subpixel bits 4)"));
  }
  const Image map = files::ReadPng(dir / "engine-map.png");
  CHECK(Count(map, {255, 0, 0}) == 0);
  CHECK(Count(map, {0, 64, 255}) == 0);

  // Without the clear colour it was drawn with, every background pixel reads as covered.
  const test::CliResult wrong = test::RunCli({"verify", "--coverage", kScene, engine.string(), "--json", "--no-map"});
  INFO(wrong.out << wrong.err);
  CHECK(wrong.exit_code == 1);
  const auto j = nlohmann::json::parse(wrong.out);
  CHECK(j["format"] == "twinraster.verify-coverage/2");
  CHECK(j["background_from"] == "scene");
  CHECK(j["pixels"]["spills"] == j["pixels"]["certainly_uncovered"]);
  CHECK(j["pixels"]["spills"].get<std::uint64_t>() > 0);
}

TEST_CASE("verify --coverage: a field of view 1 % off fails (exit 1) and the map shows its pixels red or blue",
          "[cli][verify][coverage]") {
  const test::TempDir dir;
  nlohmann::json scene = nlohmann::json::parse(std::ifstream(kScene));
  scene["viewport"]["width"] = scene["viewport"]["width"].get<double>() * 1.01;
  scene["viewport"]["height"] = scene["viewport"]["height"].get<double>() * 1.01;
  std::ofstream(dir / "wide.json") << scene.dump();
  const auto engine = Engine(TwinImage(dir, (dir / "wide.json").string(), "wide.png"), kSceneClear, dir / "bug.png");
  const test::CliResult r = test::RunCli({"verify", "--coverage", kScene, engine.string(), "--json"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 1);
  const auto j = nlohmann::json::parse(r.out);
  CHECK(j["verdict"] == "failed");
  const std::uint64_t spills = j["pixels"]["spills"], holes = j["pixels"]["holes"];
  CHECK(spills + holes == j["pixels"]["violations"].get<std::uint64_t>());
  CHECK(spills + holes > 0);
  const Image map = files::ReadPng(dir / "bug-map.png");
  CHECK(Count(map, {255, 0, 0}) == spills);
  CHECK(Count(map, {0, 64, 255}) == holes);
  const test::CliResult text = test::RunCli({"verify", "--coverage", kScene, engine.string(), "--no-map"});
  CHECK(text.exit_code == 1);
  CHECK_THAT(text.out, HasSubstring("coverage fails: "));
}

TEST_CASE("verify --coverage: a camera inside a cube covers everything, so the judgement is inconclusive (exit 6)",
          "[cli][verify][coverage]") {
  const test::TempDir dir;
  const std::string scene = test::SourcePath("scenes/hard/camera-inside-cube.json").string();
  const auto twin = TwinImage(dir, scene, "inside.png");
  const test::CliResult r = test::RunCli({"verify", "--coverage", scene, twin.string(), "--no-map"});
  INFO(r.out << r.err);
  CHECK(r.exit_code == 6);
  CHECK_THAT(r.out, HasSubstring("coverage is inconclusive: "));
  CHECK_THAT(r.out, HasSubstring("an image covered everywhere would pass too"));
}

TEST_CASE("verify --coverage: a malformed --background or --hole-tolerance, or either without --coverage, exits 2",
          "[cli][verify][coverage]") {
  const test::TempDir dir;
  const auto twin = TwinImage(dir, kScene, "twin.png");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{"--coverage", "--background", "256,0,0"}, "--background: expects a colour as R,G,B (each 0..255) or #rrggbb"},
      {{"--coverage", "--background", "1,2"}, "not \"1,2\""},
      {{"--coverage", "--background", "1,2,3,4"}, "not \"1,2,3,4\""},
      {{"--coverage", "--background", "-1,2,3"}, "not \"-1,2,3\""},
      {{"--coverage", "--background", "#12345"}, "not \"#12345\""},
      {{"--coverage", "--background", "#12345g"}, "not \"#12345g\""},
      {{"--coverage", "--background", "red"}, "not \"red\""},
      {{"--coverage", "--hole-tolerance", "150"}, "--hole-tolerance: expects a percentage from 0 to 100"},
      {{"--coverage", "--hole-tolerance", "-1"}, "not \"-1\""},
      {{"--coverage", "--hole-tolerance", "1%"}, "not \"1%\""},
      {{"--background", "1,2,3"}, "--background needs --coverage"},
      {{"--hole-tolerance", "1"}, "--hole-tolerance needs --coverage"},
  };
  for (const auto& [options, message] : cases) {
    std::vector<std::string> args = {"verify", kScene, twin.string()};
    args.insert(args.end(), options.begin(), options.end());
    const test::CliResult r = test::RunCli(args);
    INFO(options.back() << ": " << r.err);
    CHECK(r.exit_code == 2);
    CHECK_THAT(r.err, HasSubstring(message));
    CHECK(r.out.empty());
    CHECK(!std::filesystem::exists(dir / "twin-map.png"));
  }
}

TEST_CASE("verify --help documents --coverage, --background and --hole-tolerance", "[cli][verify][coverage]") {
  const test::CliResult r = test::RunCli({"verify", "--help"});
  CHECK(r.exit_code == 0);
  for (const char* s :
       {"--coverage", "--background", "--hole-tolerance", "Judging coverage only", "alpha is not read"}) {
    INFO(s);
    CHECK_THAT(r.out, HasSubstring(s));
  }
}
