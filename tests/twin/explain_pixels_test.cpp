// explain's framebuffer coordinates are where the renderers really draw: the pixel under the
// centroid of a visible triangle, traced by `explain --json`, has that triangle's colour.
#include "chain/draw_list.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <nlohmann/json.hpp>

using namespace twinraster;

TEST_CASE("explain's framebuffer points land on the pixels the renderers colour", "[twin][explain]") {
  // cgfs-scene: one cube at (-1.5, 0, 7) seen from the origin; its z = -1 face (blue, triangles
  // (5, 4, 7) and (5, 7, 6)) faces the camera. Triangle (4, 0, 3), green, is its right side.
  const std::string file = test::SourcePath("scenes/cgfs-scene.json").string();
  const test::CliResult r = test::RunCli({"explain", file, "--json"});
  REQUIRE(r.exit_code == 0);
  const auto vertices = nlohmann::json::parse(r.out)["instances"][0]["vertices"];
  const test::TwinResult images = test::RenderTwins(BuildDrawList(LoadScene(file)));
  REQUIRE(images.Equal());

  struct Case {
    std::array<std::size_t, 3> triangle;
    std::array<std::uint8_t, 3> colour;
  };
  for (const Case& c : {Case{{5, 4, 7}, {0, 0, 255}}, Case{{5, 7, 6}, {0, 0, 255}}, Case{{4, 0, 3}, {0, 255, 0}}}) {
    double x = 0, y = 0;
    for (const std::size_t v : c.triangle) {
      x += vertices[v]["framebuffer"][0].get<double>() / 3;
      y += vertices[v]["framebuffer"][1].get<double>() / 3;
    }
    // Pixel (i, j) covers [i, i + 1) x [j, j + 1), rows counted from the top.
    const auto px = static_cast<std::uint32_t>(x), py = static_cast<std::uint32_t>(y);
    INFO("centroid (" << x << ", " << y << ")");
    const std::uint8_t* pixel = images.cpu.pixel(px, py);
    REQUIRE(std::array<std::uint8_t, 3>{pixel[0], pixel[1], pixel[2]} == c.colour);
  }
  // And the vertical flip is right: vertex 5 (-1, 1, -1) is above vertex 6 (-1, -1, -1) in the
  // world, so it has the smaller framebuffer row.
  REQUIRE(vertices[5]["framebuffer"][1].get<double>() < vertices[6]["framebuffer"][1].get<double>());
}
