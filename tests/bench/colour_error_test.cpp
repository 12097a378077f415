// The bench's colour error on lit scenes: the metric by hand, the triangle numbering it relies
// on, that it sees a wrong light, and that every row of a lit scene (a wireframe one too) reports
// it in the table, the CSV and the JSON while unlit scenes leave it out.
#include "bench/bench_suite.hpp"
#include "bench/error_metrics.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "truth/truth_renderer.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdint>
#include <sstream>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

void SetPixel(Image& image, std::size_t p, Rgb8 c) {
  image.rgba[4 * p] = c.r;
  image.rgba[4 * p + 1] = c.g;
  image.rgba[4 * p + 2] = c.b;
  image.rgba[4 * p + 3] = 255;
}

// Surface number n as SurfaceList colours it: 24-bit RGB, red lowest.
Rgb8 SurfaceColour(std::uint32_t n) {
  return Rgb8{static_cast<std::uint8_t>(n), static_cast<std::uint8_t>(n >> 8), static_cast<std::uint8_t>(n >> 16)};
}

// Squares of two triangles facing the camera, one at each of `where` (half-size 1), lit flat by
// a light along the view and `ambient`.
Scene LitSquares(const std::vector<glm::dvec3>& where, double ambient) {
  Scene scene;
  scene.canvas = Canvas{.width = 96, .height = 64, .background = Rgb8{0, 0, 0}};
  scene.viewport = Viewport{.width = 1.5, .height = 1.0, .distance = 1.0};
  Model square;
  square.name = "square";
  square.shading = Shading::kFlat;
  square.vertices = {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 0)};
  square.triangles = {Triangle{{0, 2, 1}, Rgb8{255, 255, 255}}, Triangle{{0, 3, 2}, Rgb8{255, 200, 100}}};
  scene.models.push_back(square);
  for (const glm::dvec3& p : where) {
    Instance instance;
    instance.transform.translation = p;
    scene.instances.push_back(instance);
  }
  scene.lighting = Lighting{
      .ambient = ambient, .lights = {Light{.kind = Light::Kind::kDirectional, .vector = {0, 0, -1}, .intensity = 0.5}}};
  return scene;
}

// The text table's row for (scene, method), or "".
std::string TableRow(const std::string& table, const std::string& scene, const std::string& method) {
  std::istringstream lines(table);
  for (std::string line; std::getline(lines, line);) {
    std::istringstream words(line);
    std::string first, second;
    words >> first >> second;
    if (first == scene && second == method) return line;
  }
  return "";
}

}  // namespace

TEST_CASE("SameSurfaceColourError: the largest channel difference where the image shows the truth's triangle",
          "[bench][lighting]") {
  // Five pixels in a row. The truth shows background, surface 1, 1, 2, 2.
  truth::TruthImage truth{Image(5, 1), {0, 1, 1, 2, 2}};
  Image image(5, 1), surfaces(5, 1);
  const Rgb8 truth_colours[5] = {{0, 0, 0}, {100, 100, 100}, {100, 100, 100}, {40, 50, 60}, {40, 50, 60}};
  const Rgb8 image_colours[5] = {{90, 0, 0}, {100, 103, 100}, {160, 100, 100}, {40, 50, 53}, {40, 50, 60}};
  const std::uint32_t shown[5] = {0, 1, 2, 2, 2};  // pixel 2 shows another triangle than the truth
  for (std::size_t p = 0; p < 5; ++p) {
    SetPixel(truth.image, p, truth_colours[p]);
    SetPixel(image, p, image_colours[p]);
    SetPixel(surfaces, p, SurfaceColour(shown[p]));
  }
  const bench::ColourError error = bench::SameSurfaceColourError(image, surfaces, truth);
  // Pixel 0 is background and pixel 2 another triangle: left out, however far their colours are.
  CHECK(error.max_channel == 7);
  CHECK(error.pixels == 3);
  // Surface numbers use all 24 bits: 0x010203 is not 0x030201.
  truth.surfaces = {0, 0x010203, 0, 0, 0};
  SetPixel(surfaces, 1, Rgb8{0x03, 0x02, 0x01});
  CHECK(bench::SameSurfaceColourError(image, surfaces, truth).pixels == 1);
  SetPixel(surfaces, 1, Rgb8{0x01, 0x02, 0x03});
  CHECK(bench::SameSurfaceColourError(image, surfaces, truth).pixels == 0);
  // Images that do not match in size compare nothing.
  CHECK(bench::SameSurfaceColourError(Image(4, 1), surfaces, truth).pixels == 0);
}

TEST_CASE("SurfaceList numbers each draw's triangles after the earlier draws', as the truth's surfaces do",
          "[bench][lighting]") {
  const Scene scene = LitSquares({{-1.5, 0, 5}, {1.5, 0, 5}}, 0.2);
  const DrawList list = BuildDrawList(scene);
  const std::optional<DrawList> ids = bench::SurfaceList(list);
  REQUIRE(ids.has_value());
  CHECK_FALSE(ids->lighting.has_value());
  const Image shown = cpu::RenderOnCpu(*ids);
  const truth::ExactLight light(scene);
  const truth::TruthImage truth = truth::RenderTruthSurfaces(list, truth::ExactClipSpace(scene), &light);
  std::uint64_t same = 0, covered = 0, per_surface[5] = {0, 0, 0, 0, 0};
  for (std::size_t p = 0; p < truth.surfaces.size(); ++p) {
    const std::uint8_t* c = &shown.rgba[4 * p];
    const std::uint64_t id = c[0] | std::uint64_t{c[1]} << 8 | std::uint64_t{c[2]} << 16;
    REQUIRE(id <= 4);
    REQUIRE(truth.surfaces[p] <= 4);
    ++per_surface[truth.surfaces[p]];
    same += id == truth.surfaces[p] && id != 0;
    covered += truth.surfaces[p] != 0;
  }
  // Draw 1's triangles are 3 and 4; every triangle shows; the two agree but on edge pixels.
  for (int s = 1; s <= 4; ++s) CHECK(per_surface[s] > 150);
  CHECK(covered - same < covered / 20);
}

TEST_CASE("The colour error sees a wrong light: more ambient is off by what it adds", "[bench][lighting]") {
  const Scene scene = LitSquares({{0, 0, 5}}, 0.25);
  Scene brighter = scene;
  brighter.lighting->ambient = 0.35;  // I = 0.85 instead of 0.75: white goes from 191.25 to 216.75
  const DrawList list = BuildDrawList(scene);
  const truth::ExactLight light(scene);
  const truth::TruthImage truth = truth::RenderTruthSurfaces(list, truth::ExactClipSpace(scene), &light);
  const Image surfaces = cpu::RenderOnCpu(*bench::SurfaceList(list));
  const bench::ColourError right = bench::SameSurfaceColourError(cpu::RenderOnCpu(list), surfaces, truth);
  const bench::ColourError wrong =
      bench::SameSurfaceColourError(cpu::RenderOnCpu(BuildDrawList(brighter)), surfaces, truth);
  CHECK(right.max_channel <= 1);
  CHECK(wrong.max_channel >= 25);
  CHECK(wrong.max_channel <= 27);
  CHECK(right.pixels > 500);
  CHECK(wrong.pixels == right.pixels);
}

TEST_CASE("bench on a lit wireframe scene measures it filled and lit: the table, CSV and JSON carry its colour error",
          "[bench][lighting][cli]") {
  const test::TempDir dir;
  std::filesystem::create_directory(dir / "scenes");
  // A square of two flat-lit triangles, drawn as a wireframe by render; the bench fills it.
  test::WriteFile(dir / "scenes" / "lit-wire.json", R"({
    "canvas": { "width": 64, "height": 64, "background": [0, 0, 0] },
    "viewport": { "width": 1, "height": 1, "distance": 1 },
    "camera": { "position": [0, 0, 0] },
    "wireframe": true,
    "lighting": { "ambient": 0.2, "lights": [{ "type": "point", "position": [0.3, -0.4, 3], "intensity": 0.7 }] },
    "models": { "square": { "shading": "flat", "vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
                            "triangles": [[0, 2, 1, "white"], [2, 0, 3, "white"]] } },
    "instances": [{ "model": "square", "transform": { "translation": [0, 0, 5] } }]
  })");
  const test::CliResult r = test::RunCli({"bench", "--runs", "1", "--methods", "compose-f32,cpu-twin", "--scenes",
                                          (dir / "scenes").string(), "--out", (dir / "out").string(), "--json", "-q"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  const auto j = nlohmann::json::parse(r.out);
  REQUIRE(j["rows"].size() >= 2);
  for (const auto& row : j["rows"]) {
    INFO(row.dump());
    REQUIRE(row["colour_error"].is_number_integer());
    CHECK(row["colour_error"].get<int>() <= 1);
    // The filled square is about 25.6 pixels wide: most of its 655 pixels are compared.
    CHECK(row["colour_pixels"].get<int>() > 500);
    CHECK(row["image_error_px"].get<int>() < 20);  // filled, as the truth: a few edge pixels at most
  }
  const std::string csv = test::ReadFile(dir / "out" / "bench.csv");
  const std::string colour = std::to_string(j["rows"][0]["colour_error"].get<int>()) + "," +
                             std::to_string(j["rows"][0]["colour_pixels"].get<int>()) + "\n";
  CHECK(csv.find("lit-wire,compose-f32,") != std::string::npos);
  CHECK(csv.find(colour) != std::string::npos);  // the last two columns of the first row
  const std::string table = test::ReadFile(dir / "out" / "bench.txt");
  const std::string row = TableRow(table, "lit-wire", "compose-f32");
  CHECK(row.find(std::to_string(j["rows"][0]["colour_error"].get<int>()) + " (" +
                 std::to_string(j["rows"][0]["colour_pixels"].get<int>()) + ")") != std::string::npos);
}
