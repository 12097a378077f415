// The book's renderer on small scenes: the scene's background, instances in order, and the
// scenes it refuses (odd canvases, vertices projecting out of reach) with where and why.
#include "book/book_renderer.hpp"

#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <string>

using namespace twinraster;
using namespace twinraster::book;

namespace {

// A red triangle "t" with vertices (0, 0, z0), (1, 0, 2), (0, 1, 2) and an unused (0, 0, 0), and
// the same triangle in blue, "u", at z0 = 2; instanced by `instances`.
Scene TriangleScene(const std::string& canvas, double z0, const std::string& instances) {
  return ParseScene(R"({"canvas": )" + canvas + R"(, "viewport": {"width": 1, "height": 1, "distance": 1},
      "camera": {"position": [0, 0, 0]},
      "models": {"t": {"vertices": [[0, 0, )" +
                        std::to_string(z0) + R"(], [1, 0, 2], [0, 1, 2], [0, 0, 0]],
                       "triangles": [[0, 1, 2, "red"]]},
                 "u": {"vertices": [[0, 0, 2], [1, 0, 2], [0, 1, 2]], "triangles": [[0, 1, 2, "blue"]]}},
      "instances": )" + instances +
                        "}",
                    "test.json");
}

std::size_t Count(const Image& image, Rgb8 colour) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    n += image.rgba[i] == colour.r && image.rgba[i + 1] == colour.g && image.rgba[i + 2] == colour.b;
  }
  return n;
}

std::string ErrorOf(const Scene& scene) {
  try {
    RenderScene(scene);
  } catch (const BookRulesError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("The book's renderer starts from the scene's background and draws later instances over earlier ones",
          "[book][renderer]") {
  // Canvas 8 x 8, so columns 4 + (x|0) and rows 3 - (y|0). The triangle at z = 2 projects to
  // (0, 0), (4, 0), (0, 4); 4 is off the canvas (column 8, row -1). The unused vertex 3 sits at
  // z = 0 and is never looked at.
  const Image red =
      RenderScene(TriangleScene(R"({"width": 8, "height": 8, "background": [10, 20, 30]})", 2, R"([{"model": "t"}])"));
  REQUIRE(red.width == 8);
  const std::uint8_t* corner = red.pixel(0, 7);
  REQUIRE((corner[0] == 10 && corner[1] == 20 && corner[2] == 30 && corner[3] == 255));
  const std::uint8_t* origin = red.pixel(4, 3);
  REQUIRE((origin[0] == 255 && origin[1] == 0 && origin[2] == 0 && origin[3] == 255));
  // Row 3, columns 4..7 (x = 0..3); column 4, rows 2..0 (y = 1..3); and the hypotenuse from (4, 0)
  // to (0, 4), which has |dx| == |dy| and so steps along y: its on-canvas pixels are (7, 2), (6, 1),
  // (5, 0). 4 + 3 + 3.
  REQUIRE(Count(red, {255, 0, 0}) == 10);
  REQUIRE(Count(red, {10, 20, 30}) == 64 - 10);
  // The blue copy drawn after the red one covers it pixel for pixel.
  const Image both =
      RenderScene(TriangleScene(R"({"width": 8, "height": 8})", 2, R"([{"model": "t"}, {"model": "u"}])"));
  REQUIRE(Count(both, {255, 0, 0}) == 0);
  REQUIRE(Count(both, {0, 0, 255}) == 10);
}

TEST_CASE("The book's rules refuse an odd canvas, and a drawn vertex that projects out of reach", "[book][renderer]") {
  const std::string odd = ErrorOf(TriangleScene(R"({"width": 7, "height": 8})", 2, R"([{"model": "t"}])"));
  REQUIRE(odd.rfind("canvas: the book's rules need an even width and height (this canvas is 7 x 8)", 0) == 0);

  // Vertex 0 on the camera plane: 0/0 is not a number; the demo would walk forever.
  const std::string plane = ErrorOf(TriangleScene(R"({"width": 8, "height": 8})", 0, R"([{"model": "t"}])"));
  REQUIRE(plane.rfind("instances[0]: model \"t\" triangle 0: vertex 0 is at camera-space z = 0 and projects to no "
                      "canvas point; the demos walk every step of a line",
                      0) == 0);

  // Vertex 1 of "near" at (1, 0, 2^-20) projects to x = 2^20 · 8 = 8388608, beyond 2^20. Named by
  // its place in the file: the grid's two copies are Scene instances 0 and 1, the file's second
  // instance is Scene instance 2.
  const Scene near = ParseScene(R"({"canvas": {"width": 8, "height": 8}, "camera": {"position": [0, 0, 0]},
      "viewport": {"width": 1, "height": 1, "distance": 1},
      "models": {"near": {"vertices": [[0, 0, 2], [1, 0, 9.5367431640625e-07], [0, 1, 2]],
                          "triangles": [[0, 1, 2, "red"]]},
                 "ok": {"vertices": [[0, 0, 2], [1, 0, 2], [0, 1, 2]], "triangles": [[0, 1, 2, "red"]]}},
      "instances": [{"model": "ok", "grid": {"count": [2, 1, 1], "spacing": [0, 0, 0]}}, {"model": "near"}]})",
                                "near.json");
  REQUIRE(ErrorOf(near) ==
          "instances[1]: model \"near\" triangle 0: vertex 1 is at camera-space z = "
          "9.5367431640625e-07 and projects to canvas (8388608, 0); the demos walk every step of a "
          "line, on the canvas or off it, so the book's rules stop at 2^20 pixels from the centre "
          "(the Vulkan rules clip instead)");
  // The same vertex in a grid's second copy.
  const Scene grid = ParseScene(R"({"canvas": {"width": 8, "height": 8}, "camera": {"position": [0, 0, 0]},
      "viewport": {"width": 1, "height": 1, "distance": 1},
      "models": {"near": {"vertices": [[0, 0, 2], [1, 0, 9.5367431640625e-07], [0, 1, 2]],
                          "triangles": [[0, 1, 2, "red"]]}},
      "instances": [{"model": "near", "transform": {"translation": [0, 0, 1]}},
                    {"model": "near", "transform": {"translation": [0, 0, 0.5]},
                     "grid": {"count": [1, 1, 2], "spacing": [0, 0, -1]}}]})",
                                "grid.json");
  // The copies move by 0.5 ∓ 0.5 along z: copy 0 by 1 (vertex 1 at z = 1 + 2^-20, fine), copy 1 by 0.
  REQUIRE(ErrorOf(grid).rfind("instances[1] (grid copy 1): model \"near\" triangle 0: vertex 1", 0) == 0);
}

TEST_CASE("The book's rules refuse what the demos cannot express: an orthographic viewport, a transform list",
          "[book][renderer]") {
  const std::string ortho = ErrorOf(LoadScene(test::SourcePath("scenes/catlike-orthographic.json")));
  REQUIRE(ortho.rfind("viewport.projection: the book's demos only project in perspective", 0) == 0);
  const std::string listed = ErrorOf(LoadScene(test::SourcePath("scenes/cgfs-figure-10-4.json")));
  REQUIRE(listed.rfind("instances[1].transform: a transform written as a list of steps", 0) == 0);
}
