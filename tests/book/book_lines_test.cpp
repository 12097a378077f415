// Interpolate and DrawLine as the demo runs them: accumulated values, step counts that depend on
// the start's fraction, both branches with their swaps, and lines that are 8-connected.
#include "book/book_lines.hpp"

#include "support/catch.hpp"

#include <cmath>
#include <cstdint>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

using namespace twinraster;
using namespace twinraster::book;

namespace {

constexpr Rgb8 kWhite{255, 255, 255}, kRed{255, 0, 0}, kBlue{0, 0, 255};

using Pixel = std::pair<int, int>;  // column, row

// The pixels of `image` that have `colour`.
std::set<Pixel> PixelsOf(const Image& image, Rgb8 colour) {
  std::set<Pixel> pixels;
  for (std::uint32_t row = 0; row < image.height; ++row)
    for (std::uint32_t column = 0; column < image.width; ++column) {
      const std::uint8_t* p = image.pixel(column, row);
      if (p[0] == colour.r && p[1] == colour.g && p[2] == colour.b) pixels.insert({int(column), int(row)});
    }
  return pixels;
}

std::set<Pixel> Line(CanvasPoint p0, CanvasPoint p1, std::uint32_t size = 20) {
  DemoCanvas canvas(size, size, kWhite);
  DrawLine(canvas, p0, p1, kRed);
  return PixelsOf(canvas.image(), kRed);
}

// Whether every pixel of `pixels` reaches every other through 8-neighbours within the set.
bool EightConnected(const std::set<Pixel>& pixels) {
  if (pixels.empty()) return true;
  std::set<Pixel> reached{*pixels.begin()};
  std::vector<Pixel> todo{*pixels.begin()};
  while (!todo.empty()) {
    const Pixel p = todo.back();
    todo.pop_back();
    for (int dc = -1; dc <= 1; ++dc)
      for (int dr = -1; dr <= 1; ++dr) {
        const Pixel q{p.first + dc, p.second + dr};
        if (pixels.count(q) && reached.insert(q).second) todo.push_back(q);
      }
  }
  return reached.size() == pixels.size();
}

}  // namespace

TEST_CASE("Interpolate accumulates d += a instead of recomputing d0 + k·a", "[book][lines]") {
  // a = 1/10 = 0.1; ten additions of 0.1 make 0.9999999999999999, not 1 (checked in node).
  const std::vector<double> values = Interpolate(0, 0, 10, 1);
  REQUIRE(values.size() == 11);
  REQUIRE(values[0] == 0);
  REQUIRE(values[3] == 0.30000000000000004);
  REQUIRE(values[10] == 0x1.fffffffffffffp-1);
  REQUIRE(values[10] != 1.0);
}

TEST_CASE("Interpolate gives floor(i1 - i0) + 1 values, i keeping i0's fraction, and one value when i0 == i1",
          "[book][lines]") {
  // i = 0.75, 1.75, 2.75; 3.75 > 3.5 stops: 3 values = floor(2.75) + 1, though the integers
  // 0..3 under the span are 4.
  REQUIRE(Interpolate(0.75, 0, 3.5, 11).size() == 3);
  // i = 0.25, 1.25, 2.25, 3.25: 4 values = floor(3.25) + 1; a = 1/3.25.
  const std::vector<double> four = Interpolate(0.25, 1, 3.5, 2);
  REQUIRE(four.size() == 4);
  REQUIRE(four[1] == 1 + 1 / 3.25);
  // A whole span reaches i1 itself: 0, 1, 2, 3.
  REQUIRE(Interpolate(0, 5, 3, 8) == std::vector<double>{5, 6, 7, 8});
  REQUIRE(Interpolate(2.5, 7, 2.5, 9) == std::vector<double>{7});
  REQUIRE(Interpolate(3, 0, 1, 1).empty());  // i1 < i0: DrawLine never asks, having swapped
}

TEST_CASE("DrawLine steps along x when |dx| > |dy|, left to right, reading ys at (x - x0) | 0", "[book][lines]") {
  // 20 x 20: column 10 + (x|0), row 9 - (y|0). From (3.5, 1) to (-2.5, 0): dx = -6, so the points
  // swap and x = -2.5, -1.5, ..., 3.5 (7 steps); ys = 0, 1/6, 2/6, ... accumulated, so the last is
  // 0.9999999999999999 (not 1) and truncates to row 9, not 8. x = -0.5 and 0.5 both truncate to
  // column 10: 7 steps, 6 pixels.
  const std::set<Pixel> expected{{8, 9}, {9, 9}, {10, 9}, {11, 9}, {12, 9}, {13, 9}};
  REQUIRE(Line({3.5, 1}, {-2.5, 0}) == expected);
  REQUIRE(Line({-2.5, 0}, {3.5, 1}) == expected);
}

TEST_CASE("DrawLine steps along y when |dx| <= |dy|, bottom to top, and at |dx| == |dy| the far end can be missed",
          "[book][lines]") {
  // From (0.5, 2.5) to (1.5, -3.5): dy = -6, swap; y = -3.5 ... 2.5 (7 steps), xs from 1.5 by
  // a = -1/6 each step, accumulated: 1.5, 1.33, 1.17, 0.99999999999999989 (checked in node; 1.5 + 3a
  // recomputed would be 1), 0.83, 0.67, 0.5 -> columns 11, 11, 11, 10, 10, 10, 10; rows 9 - (y|0):
  // -3.5 -> 12, -2.5 -> 11, -1.5 -> 10, -0.5 and 0.5 -> 9, 1.5 -> 8, 2.5 -> 7.
  const std::set<Pixel> steep = Line({0.5, 2.5}, {1.5, -3.5});
  REQUIRE(steep == std::set<Pixel>{{11, 12}, {11, 11}, {11, 10}, {10, 9}, {10, 8}, {10, 7}});  // 7 steps, 6 pixels
  REQUIRE(EightConnected(steep));

  // |dx| == |dy| = 2.5 goes to the y branch: from (1, 1) to (3.5, -1.5), dy < 0 swaps, so the walk
  // starts at (3.5, -1.5): y = -1.5, -0.5, 0.5 (1.5 > 1 stops), x = 3.5, 2.5, 1.5 -> canvas
  // pixels (3, -1), (2, 0), (1, 0). Along x it would have been (1, 1), (2, 0), (3, -1). Either
  // way the walk misses one end: here (1, 1), the point the line was asked to start from.
  REQUIRE(Line({1, 1}, {3.5, -1.5}) == std::set<Pixel>{{13, 10}, {12, 9}, {11, 9}});
}

TEST_CASE("DrawLine: a point is one pixel, and endpoints beyond 2^20 pixels or not numbers are refused",
          "[book][lines]") {
  REQUIRE(Line({-3.7, 4.2}, {-3.7, 4.2}) == std::set<Pixel>{{7, 5}});
  DemoCanvas canvas(20, 20, kWhite);
  REQUIRE_THROWS_AS(DrawLine(canvas, {0, 0}, {2e6, 1}, kRed), std::invalid_argument);
  REQUIRE_THROWS_AS(DrawLine(canvas, {std::nan(""), 0}, {1, 1}, kRed), std::invalid_argument);
  REQUIRE_THROWS_AS(DrawLine(canvas, {0, 0}, {1, -INFINITY}, kRed), std::invalid_argument);
  REQUIRE(PixelsOf(canvas.image(), kRed).empty());
  // Far off the canvas but within reach: walked, and every pixel dropped but the canvas's own.
  DrawLine(canvas, {-9.5, 0.5}, {1e5, 0.5}, kRed);
  // x = -9.5, -8.5, ...: columns 1..19 (x = -0.5 and 0.5 both on column 10), row 9; then off.
  REQUIRE(PixelsOf(canvas.image(), kRed).size() == 19);
}

TEST_CASE("Lines are 8-connected, start on the truncated start point, and do not depend on direction",
          "[book][lines]") {
  // 200 lines with endpoints on a 1/8 grid in [-30, 30) (exact steps, so no rounding of x or y),
  // from a fixed linear congruential sequence.
  std::uint32_t state = 12345;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return static_cast<double>((state >> 16) % 480) / 8.0 - 30.0;  // 0..479 eighths, minus 30
  };
  for (int i = 0; i < 200; ++i) {
    const CanvasPoint a{next(), next()}, b{next(), next()};
    INFO("(" << a.x << ", " << a.y << ") to (" << b.x << ", " << b.y << ")");
    const std::set<Pixel> pixels = Line(a, b, 64);
    REQUIRE(pixels == Line(b, a, 64));
    REQUIRE(EightConnected(pixels));
    // The walk starts at the end with the smaller coordinate along the longer axis (a tie goes to y).
    const bool along_x = std::abs(b.x - a.x) > std::abs(b.y - a.y);
    const CanvasPoint start = along_x ? (a.x <= b.x ? a : b) : (a.y <= b.y ? a : b);
    REQUIRE(pixels.count({32 + int(std::trunc(start.x)), 31 - int(std::trunc(start.y))}));
    // No pixel outside the box of the two ends' pixels.
    for (const Pixel& p : pixels) {
      REQUIRE(p.first >= 32 + int(std::trunc(std::min(a.x, b.x))));
      REQUIRE(p.first <= 32 + int(std::trunc(std::max(a.x, b.x))));
      REQUIRE(p.second >= 31 - int(std::trunc(std::max(a.y, b.y))));
      REQUIRE(p.second <= 31 - int(std::trunc(std::min(a.y, b.y))));
    }
  }
}

TEST_CASE("DrawWireframeTriangle draws its three edges, and a later triangle's pixels replace an earlier one's",
          "[book][lines]") {
  DemoCanvas canvas(20, 20, kWhite);
  DrawWireframeTriangle(canvas, {-5, -5}, {5, -5}, {0, 5}, kRed);
  std::set<Pixel> edges = Line({-5, -5}, {5, -5});
  for (const Pixel& p : Line({5, -5}, {0, 5})) edges.insert(p);
  for (const Pixel& p : Line({-5, -5}, {0, 5})) edges.insert(p);
  REQUIRE(PixelsOf(canvas.image(), kRed) == edges);
  // A second triangle sharing the bottom edge: where its pixels fall, its colour wins.
  DrawWireframeTriangle(canvas, {5, -5}, {-5, -5}, {0, -8}, kBlue);
  std::set<Pixel> blue_edges = Line({5, -5}, {-5, -5});
  for (const Pixel& p : Line({-5, -5}, {0, -8})) blue_edges.insert(p);
  for (const Pixel& p : Line({5, -5}, {0, -8})) blue_edges.insert(p);
  const std::set<Pixel> red = PixelsOf(canvas.image(), kRed), blue = PixelsOf(canvas.image(), kBlue);
  REQUIRE(blue == blue_edges);
  for (const Pixel& p : Line({-5, -5}, {5, -5})) REQUIRE(blue.count(p));  // the shared edge is blue
  for (const Pixel& p : edges) REQUIRE(red.count(p) == 1 - blue.count(p));
}
