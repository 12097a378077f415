// Figures 10-2, 10-3 and 10-10 drawn by the book's rules, against the chapter's demo pages.
//
// Where the expected numbers come from:
// - each cube vertex's pixel: its camera-space point in exact arithmetic (by hand for 10-2 and
//   10-3; with √3 and cos/sin of 195° and -30° to 50 digits for 10-10), the canvas point
//   (x·600/z, y·600/z), column 300 + trunc(x), row 300 - trunc(y) - 1. The doubles truncate the
//   same way: 10-2's points are halves and whole numbers that the doubles hit exactly (-50 and 100
//   after rounding, see book_projection_test.cpp), 10-3's fractions are at least 0.07 from a whole
//   number, 10-10's at least 1.4e-4. Every vertex's pixel is painted (a line starts there or
//   crosses it). Its colour is the last face drawn with that corner: purple (triangles 8 and 9)
//   for the top vertices 0, 1, 4, 5, cyan (10 and 11, the last) for the bottom ones 2, 3, 6, 7.
// - the pixel counts per colour: the book's own demo pages (demos/raster-06.html, raster-07.html,
//   raster-08.html of github.com/ggambetta/computer-graphics-from-scratch at commit 9e1e75c) run
//   under node with a stand-in canvas by tests/book/run_demo_page.mjs. That run's canvases equal
//   this renderer's images pixel for pixel (twinraster compare: 0 differing pixels, all three).
#include "book/book_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <map>
#include <string>
#include <tuple>
#include <vector>

using namespace twinraster;

namespace {

constexpr Rgb8 kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kYellow{255, 255, 0}, kPurple{255, 0, 255},
    kCyan{0, 255, 255}, kWhite{255, 255, 255};

using Counts = std::map<std::tuple<int, int, int>, std::size_t>;

Image Render(const std::string& name) {
  return book::RenderScene(LoadScene(test::SourcePath("scenes/" + name + ".json")));
}

Counts CountColours(const Image& image) {
  Counts counts;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    REQUIRE(image.rgba[i + 3] == 255);
    ++counts[{image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]}];
  }
  return counts;
}

std::tuple<int, int, int> Key(Rgb8 c) { return {c.r, c.g, c.b}; }

// 600 x 600: the six colours have these counts, and every other pixel is white.
void RequireCounts(const Image& image, std::size_t red, std::size_t green, std::size_t blue, std::size_t yellow,
                   std::size_t purple, std::size_t cyan) {
  REQUIRE(image.width == 600);
  REQUIRE(image.height == 600);
  const Counts counts = CountColours(image);
  const Counts expected = {{Key(kRed), red},
                           {Key(kGreen), green},
                           {Key(kBlue), blue},
                           {Key(kYellow), yellow},
                           {Key(kPurple), purple},
                           {Key(kCyan), cyan},
                           {Key(kWhite), 600 * 600 - (red + green + blue + yellow + purple + cyan)}};
  REQUIRE(counts == expected);
}

struct VertexPixel {
  int column, row;
  Rgb8 colour;
};

void RequireVertexPixels(const Image& image, const std::vector<VertexPixel>& vertices) {
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const VertexPixel& v = vertices[i];
    INFO("vertex " << i % 8 << " of instance " << i / 8 << " at column " << v.column << ", row " << v.row);
    const std::uint8_t* p = image.pixel(static_cast<std::uint32_t>(v.column), static_cast<std::uint32_t>(v.row));
    REQUIRE(Key({p[0], p[1], p[2]}) == Key(v.colour));
  }
}

// Figure 10-2's cube at (-1.5, 0, 7), camera at the origin: vertex (±1, ±1, ±1) is at camera space
// (±1 - 1.5, ±1, 7 ± 1). z = 8: x = -0.5 or -2.5 -> -0.5/8·600 = -37.5, -2.5/8·600 = -187.5 ->
// columns 263, 113; y = ±1/8·600 = ±75 -> rows 224, 374. z = 6: x -> -50, -250 -> columns 250, 50;
// y = ±100 -> rows 199, 399.
const std::vector<VertexPixel> kFirstCube = {
    {263, 224, kPurple}, {113, 224, kPurple}, {113, 374, kCyan}, {263, 374, kCyan},
    {250, 199, kPurple}, {50, 199, kPurple},  {50, 399, kCyan},  {250, 399, kCyan},
};

}  // namespace

TEST_CASE("Figure 10-2 by the book's rules: the demo's pixels", "[book][figures]") {
  const Image image = Render("cgfs-scene");
  RequireVertexPixels(image, kFirstCube);
  RequireCounts(image, 146, 314, 389, 520, 570, 570);  // 2509 painted pixels
}

TEST_CASE("Figure 10-3 by the book's rules: the demo's pixels", "[book][figures]") {
  const Image image = Render("cgfs-instances");
  std::vector<VertexPixel> vertices = kFirstCube;
  // The second cube at (1.25, 2, 7.5): camera space (1.25 ± 1, 2 ± 1, 7.5 ± 1). z = 8.5:
  // x = 2.25/8.5·600 = 158.82, 0.25/8.5·600 = 17.65 -> columns 458, 317; y = 3/8.5·600 = 211.76,
  // 1/8.5·600 = 70.59 -> rows 88, 229. z = 6.5: x = 207.69, 23.08 -> columns 507, 323;
  // y = 276.92, 92.31 -> rows 23, 207.
  vertices.insert(vertices.end(), {{458, 88, kPurple},
                                   {317, 88, kPurple},
                                   {317, 229, kCyan},
                                   {458, 229, kCyan},
                                   {507, 23, kPurple},
                                   {323, 23, kPurple},
                                   {323, 207, kCyan},
                                   {507, 207, kCyan}});
  RequireVertexPixels(image, vertices);
  RequireCounts(image, 284, 650, 753, 950, 1213, 1149);  // 4999 painted pixels
}

TEST_CASE("Figure 10-10 by the book's rules: the demo's pixels", "[book][figures]") {
  const Image image = Render("cgfs-transforms");
  // Camera space = Rᵀ(-30°) · (world - (-3, 1, 2)) with R about Y as the demo writes it
  // (Rᵀ rows [√3/2, 0, -1/2] [0, 1, 0] [1/2, 0, √3/2]); world = T + R(θ) · s·v with cube 0 at
  // T = (-1.5, 0, 7), s = 0.75, θ = 0 and cube 1 at T = (1.25, 2.5, 7.5), s = 1, θ = 195°.
  // E.g. cube 0 vertex 0: world (-0.75, 0.75, 7.75), relative (2.25, -0.25, 5.75), camera space
  // (2.25·√3/2 - 5.75/2, -0.25, 2.25/2 + 5.75·√3/2) = (-0.926443, -0.25, 6.104646), canvas
  // (-91.056, -24.571) -> column 209, row 323. The canvas points, to three decimals:
  //   cube 0: (-91.056, -24.571) (-249.370, -28.013) (-249.370, -196.091) (-91.056, -172.000143)
  //           (-22.030, -31.214) (-218.288, -36.986) (-218.288, -258.901) (-22.030, -218.495)
  //   cube 1: (102.004, 274.026) (204.249, 217.766) (204.249, 43.553) (102.004, 54.805)
  //           (-42.125, 217.766) (67.254, 180.672) (67.254, 36.134) (-42.125, 43.553)
  RequireVertexPixels(image, {
                                 {209, 323, kPurple},
                                 {51, 327, kPurple},
                                 {51, 495, kCyan},
                                 {209, 471, kCyan},
                                 {278, 330, kPurple},
                                 {82, 335, kPurple},
                                 {82, 557, kCyan},
                                 {278, 517, kCyan},
                                 {402, 25, kPurple},
                                 {504, 82, kPurple},
                                 {504, 256, kCyan},
                                 {402, 245, kCyan},
                                 {258, 82, kPurple},
                                 {367, 119, kPurple},
                                 {367, 263, kCyan},
                                 {258, 256, kCyan},
                             });
  RequireCounts(image, 389, 658, 689, 1098, 1394, 1420);  // 5648 painted pixels
}
