// Coverage at pixel centres, by hand: which centres a triangle covers, and the top-left rule on
// exact ties, with every centre of a tiled region covered exactly once.
#include "support/catch.hpp"
#include "truth_test_support.hpp"

#include <algorithm>

using namespace twinraster;
using namespace twinraster::truthtest;

namespace {

ClipTriangle Window(std::uint32_t size, glm::dvec2 a, glm::dvec2 b, glm::dvec2 c) {
  return {{FromWindow(a.x, a.y, 0.5, size, size), FromWindow(b.x, b.y, 0.5, size, size),
           FromWindow(c.x, c.y, 0.5, size, size)}};
}

ClipTriangle Reversed(ClipTriangle t) {
  std::swap(t.v[1], t.v[2]);
  return t;
}

}  // namespace

TEST_CASE("Truth coverage: a triangle covers exactly the centres inside it", "[truth][coverage]") {
  // Window (1, 1), (7, 1), (1, 7): centres (px + 0.5, py + 0.5) with x > 1, y > 1 and x + y < 8.
  // The legs are between centres; the hypotenuse runs through centres with px + py = 7, and as a
  // right edge it does not take them.
  const ClipTriangle t = Window(8, {1, 1}, {7, 1}, {1, 7});
  const PixelSet expected = PixelsWhere(0, 7, 0, 7, [](int x, int y) { return x >= 1 && y >= 1 && x + y <= 6; });
  REQUIRE(expected.size() == 15);
  CHECK(CoveredBy(8, 8, t) == expected);
  CHECK(CoveredBy(8, 8, Reversed(t)) == expected);  // either winding

  // Small triangles: one around the centre of pixel (2, 2) only, one between centres.
  CHECK(CoveredBy(8, 8, Window(8, {2.25, 2.25}, {2.875, 2.25}, {2.25, 2.875})) == PixelSet{{2, 2}});
  CHECK(CoveredBy(8, 8, Window(8, {2.6, 2.6}, {3.4, 2.6}, {2.6, 3.4})).empty());
}

TEST_CASE("Truth coverage: ties at centres follow the top-left rule", "[truth][coverage]") {
  // Vertices on centres: (1.5, 1.5), (5.5, 1.5), (1.5, 5.5). Its top edge (y = 1.5) and left edge
  // (x = 1.5) take their centres; the hypotenuse (x + y = 7), a right edge, does not.
  const ClipTriangle upper = Window(8, {1.5, 1.5}, {5.5, 1.5}, {1.5, 5.5});
  const PixelSet upper_expected = PixelsWhere(0, 7, 0, 7, [](int x, int y) { return x >= 1 && y >= 1 && x + y <= 5; });
  REQUIRE(upper_expected.size() == 10);
  CHECK(CoveredBy(8, 8, upper) == upper_expected);
  CHECK(CoveredBy(8, 8, Reversed(upper)) == upper_expected);

  // Its mirror completes the square: the shared hypotenuse is its left edge, so it takes those
  // centres; its bottom (y = 5.5) and right (x = 5.5) edges do not.
  const ClipTriangle lower = Window(8, {5.5, 5.5}, {1.5, 5.5}, {5.5, 1.5});
  const PixelSet lower_expected = PixelsWhere(0, 7, 0, 7, [](int x, int y) { return x <= 4 && y <= 4 && x + y >= 6; });
  REQUIRE(lower_expected.size() == 6);
  CHECK(CoveredBy(8, 8, lower) == lower_expected);
  CHECK(CoveredBy(8, 8, Reversed(lower)) == lower_expected);

  // Together: the centres of the square [1.5, 5.5)², each exactly once.
  const std::vector<int> counts = CoverageCounts(8, 8, {upper, Reversed(lower)});
  for (int y = 0; y < 8; ++y)
    for (int x = 0; x < 8; ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(counts[std::size_t(y * 8 + x)] == ((x >= 1 && x <= 4 && y >= 1 && y <= 4) ? 1 : 0));
    }
}

TEST_CASE("Truth coverage: a tiled region covers each centre exactly once", "[truth][coverage]") {
  // A 4 x 4 grid of cells 3 px wide, corners on pixel centres so that every edge, horizontal,
  // vertical and diagonal, runs through centres; inner corners are moved off the centres on odd
  // rows so edges also meet at arbitrary points. Diagonals and windings alternate.
  constexpr std::uint32_t kSize = 16;
  const auto corner = [](int i, int j) {
    glm::dvec2 p{1.5 + 3 * i, 1.5 + 3 * j};
    if (i > 0 && i < 4 && j > 0 && j < 4 && j % 2 == 1) p += glm::dvec2{0.3125, -0.1875};
    return p;
  };
  std::vector<ClipTriangle> triangles;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i) {
      const glm::dvec2 a = corner(i, j), b = corner(i + 1, j), c = corner(i + 1, j + 1), d = corner(i, j + 1);
      ClipTriangle t1 = Window(kSize, a, b, c), t2 = Window(kSize, a, c, d);
      if ((i + j) % 2 == 1) {
        t1 = Window(kSize, a, b, d);
        t2 = Window(kSize, b, c, d);
      }
      triangles.push_back(i % 2 == 0 ? t1 : Reversed(t1));
      triangles.push_back(j % 2 == 0 ? t2 : Reversed(t2));
    }
  // The region is [1.5, 13.5)²: its top and left edges take their centres.
  const std::vector<int> counts = CoverageCounts(kSize, kSize, triangles);
  for (int y = 0; y < int(kSize); ++y)
    for (int x = 0; x < int(kSize); ++x) {
      INFO("pixel " << x << ", " << y);
      CHECK(counts[std::size_t(y) * kSize + std::size_t(x)] == ((x >= 1 && x <= 12 && y >= 1 && y <= 12) ? 1 : 0));
    }
}

TEST_CASE("Truth coverage: zero area draws nothing, and coverage stops at the framebuffer", "[truth][coverage]") {
  // Collinear through centres, exactly.
  CHECK(CoveredBy(8, 8, Window(8, {0.5, 0.5}, {3.5, 3.5}, {6.5, 6.5})).empty());
  CHECK(CoveredBy(8, 8, Window(8, {2.5, 1.5}, {2.5, 1.5}, {5.5, 6.5})).empty());

  // A triangle far larger than the canvas (clipped to the view volume first) covers every pixel.
  const PixelSet all = PixelsWhere(0, 7, 0, 3, [](int, int) { return true; });
  const ClipTriangle huge{
      {FromWindow(-8, -8, 0.5, 8, 4), FromWindow(40, -8, 0.5, 8, 4), FromWindow(-8, 40, 0.5, 8, 4)}};
  CHECK(CoveredPixels(Render(MakeInput(8, 4, {huge}))) == all);

  // Half off the left side: only the centres on the canvas, x > 0 side of the edge x + y = 4.
  const ClipTriangle off{{FromWindow(-4, 0, 0.5, 8, 8), FromWindow(4, 0, 0.5, 8, 8), FromWindow(-4, 8, 0.5, 8, 8)}};
  CHECK(CoveredPixels(Render(MakeInput(8, 8, {off}))) ==
        PixelsWhere(0, 7, 0, 7, [](int x, int y) { return x + y <= 2; }));
}
