// Stages 4 and 5: snapping to 1/256 pixel, edge functions and the top-left rule.
#include "cpu/lavapipe/setup.hpp"

#include "cpu/lavapipe/coverage.hpp"
#include "support/catch.hpp"

#include <cmath>
#include <limits>
#include <vector>

using namespace twinraster::cpu;

namespace {

const PixelRect kRegion{0, 0, 15, 15};

TriangleSetup Setup(WindowPos a, WindowPos b, WindowPos c) {
  TriangleSetup t;
  REQUIRE(SetUpTriangle(a, b, c, kRegion, t));
  return t;
}

// Coverage of a 16x16 region by per-pixel tests, checked against the row spans on the way.
std::vector<int> CoverageOf(const TriangleSetup& t) {
  std::vector<int> covered(16 * 16, 0);
  for (int py = 0; py < 16; ++py) {
    const Span span = py >= t.bounds.y0 && py <= t.bounds.y1 ? CoveredSpan(t, py) : Span{};
    for (int px = 0; px < 16; ++px) {
      const bool hit = Covers(t, px, py);
      CHECK(hit == (px >= span.begin && px < span.end));
      covered[static_cast<std::size_t>(py * 16 + px)] = hit ? 1 : 0;
    }
  }
  return covered;
}

}  // namespace

TEST_CASE("snapping without SSE (Mesa 22.3.6 on aarch64): ties away from zero", "[cpu][snap]") {
  CHECK(SnapToSubpixelHalfAway(0.5f) == 0);
  CHECK(SnapToSubpixelHalfAway(1.5f) == 256);
  CHECK(SnapToSubpixelHalfAway(0.5f + 0.5f / 256) == 1);
  CHECK(SnapToSubpixelHalfAway(0.5f + 2.5f / 256) == 3);
  CHECK(SnapToSubpixelHalfAway(0.5f - 0.5f / 256) == -1);
  CHECK(SnapToSubpixelHalfAway(0.5f - 2.5f / 256) == -3);
  // C's (int) on aarch64: NaN to 0, saturating out of range.
  CHECK(SnapToSubpixelHalfAway(std::numeric_limits<float>::quiet_NaN()) == 0);
  CHECK(SnapToSubpixelHalfAway(1e30f) == std::numeric_limits<std::int32_t>::max());
  CHECK(SnapToSubpixelHalfAway(-1e30f) == std::numeric_limits<std::int32_t>::min());
}

TEST_CASE("snapping: (w - 0.5) * 256 rounded to nearest, ties to even", "[cpu][snap]") {
  CHECK(SnapToSubpixel(0.5f) == 0);
  CHECK(SnapToSubpixel(1.5f) == 256);
  CHECK(SnapToSubpixel(0.5f + 1.0f / 256) == 1);
  // Exactly half a subpixel: 0.5 -> 0, 1.5 -> 2, 2.5 -> 2, 3.5 -> 4 (half away from zero would
  // give 1, 2, 3, 4).
  CHECK(SnapToSubpixel(0.5f + 0.5f / 256) == 0);
  CHECK(SnapToSubpixel(0.5f + 1.5f / 256) == 2);
  CHECK(SnapToSubpixel(0.5f + 2.5f / 256) == 2);
  CHECK(SnapToSubpixel(0.5f + 3.5f / 256) == 4);
  // Negative ties: -0.5 -> 0, -1.5 -> -2, -2.5 -> -2 (away from zero: -1, -2, -3).
  CHECK(SnapToSubpixel(0.5f - 0.5f / 256) == 0);
  CHECK(SnapToSubpixel(0.5f - 1.5f / 256) == -2);
  CHECK(SnapToSubpixel(0.5f - 2.5f / 256) == -2);
  // Further out: 10.5 + 2.5/256 -> 2562.5 -> 2562; 10.5 + 3.5/256 -> 2563.5 -> 2564.
  CHECK(SnapToSubpixel(10.5f + 2.5f / 256) == 2562);
  CHECK(SnapToSubpixel(10.5f + 3.5f / 256) == 2564);
  // Nothing representable: SSE's integer indefinite.
  CHECK(SnapToSubpixel(std::numeric_limits<float>::quiet_NaN()) == std::numeric_limits<std::int32_t>::min());
  CHECK(SnapToSubpixel(1e10f) == std::numeric_limits<std::int32_t>::min());
}

TEST_CASE("edge functions and the top-left bias", "[cpu][edges]") {
  // Left edge (going down: dcdx = Yi - Yj < 0) gets +1.
  EdgeFunction left = MakeEdge(0, 0, 0, 256);
  CHECK(left.dcdx == -256);
  CHECK(left.dcdy == 0);
  CHECK(left.c == 1);
  // Right edge (going up) does not.
  EdgeFunction right = MakeEdge(0, 256, 0, 0);
  CHECK(right.dcdx == 256);
  CHECK(right.c == 0);
  // Top edge: horizontal and running toward -x, as the top edge of a positive-area triangle does.
  EdgeFunction top = MakeEdge(256, 0, 0, 0);  // dcdx == 0, dcdy > 0
  CHECK(top.dcdy == 256);
  CHECK(top.c == 1);
  EdgeFunction bottom = MakeEdge(0, 0, 256, 0);  // dcdx == 0, dcdy < 0
  CHECK(bottom.c == 0);
  // Value at pixel centres: c + dcdy * py * 256 - dcdx * px * 256.
  CHECK(EdgeAt(left, 1, 5) == 1 + 256 * 256);
  CHECK(EdgeAt(left, 0, 5) == 1);   // on the edge, biased to inside
  CHECK(EdgeAt(right, 0, 5) == 0);  // on the edge, outside
}

TEST_CASE("zero area draws nothing", "[cpu][edges]") {
  TriangleSetup t;
  CHECK_FALSE(SetUpTriangle({1.5f, 1.5f, 0}, {5.5f, 5.5f, 0}, {9.5f, 9.5f, 0}, kRegion, t));
  // Distinct float positions that snap to collinear points.
  CHECK_FALSE(SetUpTriangle({1.5f, 1.5f, 0}, {5.5f, 1.5f + 0.001f, 0}, {9.5f, 1.5f, 0}, kRegion, t));
}

TEST_CASE("top-left rule: two triangles sharing an edge through pixel centres", "[cpu][edges]") {
  // The square [2.5, 8.5]^2 (its corners are pixel centres) split along the diagonal, which also
  // runs through the pixel centres (k + 0.5, k + 0.5).
  const WindowPos a{2.5f, 2.5f, 0}, b{8.5f, 2.5f, 0}, c{8.5f, 8.5f, 0}, d{2.5f, 8.5f, 0};
  const TriangleSetup upper = Setup(a, b, c);  // above the diagonal: top edge and right edge
  const TriangleSetup lower = Setup(a, c, d);  // below it: left edge and bottom edge
  const std::vector<int> up = CoverageOf(upper);
  const std::vector<int> low = CoverageOf(lower);

  for (int py = 0; py < 16; ++py) {
    for (int px = 0; px < 16; ++px) {
      const std::size_t i = static_cast<std::size_t>(py * 16 + px);
      const bool in_square = px >= 2 && px <= 7 && py >= 2 && py <= 7;  // left/top in, right/bottom out
      INFO("pixel " << px << "," << py);
      CHECK(up[i] + low[i] == (in_square ? 1 : 0));
      // The diagonal is a left edge of `upper` (inside to its right) and a right edge of `lower`.
      CHECK(up[i] == (in_square && px >= py ? 1 : 0));
    }
  }
  // Named cases: on the top edge (row 2) covered, on the left edge (column 2) covered, on the
  // right edge (column 8) and the bottom edge (row 8) not, corners included.
  CHECK(Covers(upper, 5, 2));
  CHECK(Covers(upper, 2, 2));
  CHECK_FALSE(Covers(upper, 8, 2));
  CHECK_FALSE(Covers(upper, 8, 5));
  CHECK(Covers(lower, 2, 5));
  CHECK_FALSE(Covers(lower, 5, 8));
  CHECK_FALSE(Covers(lower, 2, 8));
}

TEST_CASE("coverage does not depend on the winding", "[cpu][edges]") {
  const WindowPos a{2.25f, 1.75f, 0}, b{12.6f, 4.1f, 0}, c{5.3f, 13.9f, 0};
  const TriangleSetup ccw = Setup(a, b, c);
  const TriangleSetup cw = Setup(a, c, b);
  CHECK(ccw.swapped != cw.swapped);
  CHECK(CoverageOf(ccw) == CoverageOf(cw));
}

TEST_CASE("coverage is limited to the draw region", "[cpu][edges]") {
  TriangleSetup t;
  REQUIRE(SetUpTriangle({-20.0f, -20.0f, 0}, {60.0f, -20.0f, 0}, {-20.0f, 60.0f, 0}, kRegion, t));
  CHECK(t.bounds.x0 == 0);
  CHECK(t.bounds.y0 == 0);
  CHECK(t.bounds.x1 == 15);
  CHECK(t.bounds.y1 == 15);
  CHECK_FALSE(SetUpTriangle({20.5f, 1.5f, 0}, {30.5f, 1.5f, 0}, {20.5f, 9.5f, 0}, kRegion, t));
}

TEST_CASE("row spans, divided or stepped, equal per-pixel edge tests on many triangles", "[cpu][edges]") {
  // Vertices on a coarse grid of quarter pixels and half subpixels, so that edges often pass
  // exactly through pixel centres.
  unsigned state = 12345u;
  const auto next = [&state] {
    state = state * 1664525u + 1013904223u;
    return state >> 8;
  };
  int set_up = 0;
  for (int n = 0; n < 2000; ++n) {
    WindowPos v[3];
    for (WindowPos& p : v) {
      p.x = -2.0f + static_cast<float>(next() % 80) * 0.25f;
      p.y = -2.0f + static_cast<float>(next() % 80) * 0.25f;
      if (next() % 4 == 0) p.x += 0.5f / 256;
    }
    TriangleSetup t;
    if (!SetUpTriangle(v[0], v[1], v[2], kRegion, t)) continue;  // degenerate, or outside the region
    ++set_up;
    SpanWalker walker(t, t.bounds.y0);
    for (int py = t.bounds.y0; py <= t.bounds.y1; ++py, walker.NextRow()) {
      const Span span = CoveredSpan(t, py);
      const Span walked = walker.span();
      REQUIRE(walked.begin == span.begin);
      REQUIRE(walked.end == span.end);
      for (int px = 0; px < 16; ++px) {
        bool inside = px >= t.bounds.x0 && px <= t.bounds.x1;
        for (const EdgeFunction& e : Edges(t)) inside = inside && EdgeAt(e, px, py) > 0;
        REQUIRE(inside == (px >= span.begin && px < span.end));
      }
    }
  }
  CHECK(set_up > 1000);  // most of the 2,000 are real triangles that reach the region
}
