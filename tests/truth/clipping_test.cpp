// Homogeneous clipping in double: triangles straddling the near plane z = 0, by hand.
#include "support/catch.hpp"
#include "truth/truth_clipping.hpp"
#include "truth_test_support.hpp"

using namespace twinraster;
using namespace twinraster::truthtest;

TEST_CASE("Truth clipping: a triangle inside the view volume is unchanged", "[truth][clipping]") {
  const glm::dvec4 a{-0.5, -0.5, 0.25, 1}, b{0.5, -0.5, 0.5, 1}, c{0, 1, 1, 1};  // c on two planes
  CHECK(truth::ClipToViewVolume(a, b, c) == truth::ClipPolygon{a, b, c});
  const glm::dvec4 nan{std::nan(""), 0, 0, 1};
  CHECK(truth::ClipToViewVolume(a, b, nan).empty());
}

TEST_CASE("Truth clipping: the near plane cuts a triangle straddling z = 0", "[truth][clipping]") {
  // 16 x 16, w = 1, window (2, 2), (14, 2), (2, 14) with clip z = -0.5, 0.5, -0.5: z = x_ndc / 1.5
  // over the triangle, so z >= 0 keeps window x >= 8. The cuts are the edge midpoints, exactly.
  const glm::dvec4 a = FromWindow(2, 2, -0.5, 16, 16), b = FromWindow(14, 2, 0.5, 16, 16),
                   c = FromWindow(2, 14, -0.5, 16, 16);
  const truth::ClipPolygon polygon = truth::ClipToViewVolume(a, b, c);
  CHECK(polygon == truth::ClipPolygon{{0, -0.75, 0, 1}, b, {0, 0, 0, 1}});

  // Left: window x = 8 (no centres on it). Top: y = 2. Hypotenuse x + y = 16 through centres with
  // px + py = 15, a right edge, so not taken.
  const PixelSet expected = PixelsWhere(0, 15, 0, 15, [](int x, int y) { return x >= 8 && y >= 2 && x + y <= 14; });
  REQUIRE(expected.size() == 15);
  CHECK(CoveredBy(16, 16, {{a, b, c}}) == expected);

  // All of it behind the near plane, or beyond the far plane (z > w): nothing.
  CHECK(CoveredBy(16, 16,
                  {{FromWindow(2, 2, -0.5, 16, 16), FromWindow(14, 2, -0.1, 16, 16), FromWindow(2, 14, -0.5, 16, 16)}})
            .empty());
  CHECK(CoveredBy(16, 16,
                  {{FromWindow(2, 2, 1.5, 16, 16), FromWindow(14, 2, 1.01, 16, 16), FromWindow(2, 14, 1.5, 16, 16)}})
            .empty());
}

TEST_CASE("Truth clipping: a vertex behind the eye (w < 0)", "[truth][clipping]") {
  // z = w - 0.5 at every vertex, so z >= 0 is w >= 0.5 and the kept part is in front of the eye.
  // A and B (w = 1) are at window (4.5, 4) and (11.5, 4); C = (0, 1, -1.5, -1) is behind. The cuts
  // on A-C and B-C are at t = 1/4: (∓21/64, -1/8, 0, 1/2), window (2.75, 6) and (13.25, 6).
  // C lies outside the x and y planes too, which cut away nothing more of the kept part.
  const glm::dvec4 a{-7.0 / 16, -0.5, 0.5, 1}, b{7.0 / 16, -0.5, 0.5, 1}, c{0, 1, -1.5, -1};
  // The trapezoid: left edge x = 4.5 - 0.875 (y - 4), right edge x = 11.5 + 0.875 (y - 4). Row 4
  // (y = 4.5): x in (4.0625, 11.9375); row 5 (y = 5.5): x in (3.1875, 12.8125). No ties.
  PixelSet expected = PixelsWhere(4, 11, 4, 4, [](int, int) { return true; });
  expected.merge(PixelsWhere(3, 12, 5, 5, [](int, int) { return true; }));
  REQUIRE(expected.size() == 18);
  CHECK(CoveredBy(16, 16, {{a, b, c}}) == expected);
  CHECK(CoveredBy(16, 16, {{c, b, a}}) == expected);
}
