// SwiftShader's set-up (cpu/swiftshader/setup.hpp): the box an outline can cover, clamped to the
// framebuffer, and the winding from the float area of the snapped vertices.
#include "cpu/swiftshader/setup.hpp"

#include "corner_triangle.hpp"
#include "support/catch.hpp"

#include <array>

using namespace twinraster::cpu;
using test::kCorner;
using test::Vertex;

TEST_CASE("SwiftShader set-up: bounds are the rows and columns whose centres the box holds",
          "[cpu][swiftshader][setup]") {
  PixelRect bounds;
  REQUIRE(OutlineBounds(kCorner.data(), 3, 100, 100, bounds));
  CHECK(bounds.x0 == 0);
  CHECK(bounds.x1 == 3);
  CHECK(bounds.y0 == 0);
  CHECK(bounds.y1 == 3);
  // Between centres: 1/16 pixel past centre 2 to 15/16 before centre 3 holds no row.
  const std::array<SnappedPoint, 3> thin = {{{0, 33}, {64, 33}, {0, 47}}};
  CHECK_FALSE(OutlineBounds(thin.data(), 3, 100, 100, bounds));
  // Clamped to the framebuffer; wholly outside covers nothing.
  const std::array<SnappedPoint, 3> big = {{{-1600, -1600}, {3200, -1600}, {-1600, 3200}}};
  REQUIRE(OutlineBounds(big.data(), 3, 10, 20, bounds));
  CHECK(bounds.x0 == 0);
  CHECK(bounds.x1 == 9);
  CHECK(bounds.y0 == 0);
  CHECK(bounds.y1 == 19);
  const std::array<SnappedPoint, 3> right = {{{320, 0}, {400, 0}, {320, 64}}};
  CHECK_FALSE(OutlineBounds(right.data(), 3, 10, 20, bounds));
}

TEST_CASE("SwiftShader set-up: the winding is the sign of the float area, turned over by each w below 0",
          "[cpu][swiftshader][setup]") {
  // Area (y0 - y2) x1 + (y2 - y1) x0 + (y1 - y0) x2: -4096 for these, +4096 with b and c swapped.
  CHECK_FALSE(OutlineWinding(Vertex(0, 0), Vertex(64, 0), Vertex(0, 64)));
  CHECK(OutlineWinding(Vertex(0, 0), Vertex(0, 64), Vertex(64, 0)));
  // One vertex behind the eye (w < 0, -0 included) turns the winding over; two turn it back.
  CHECK(OutlineWinding(Vertex(0, 0), Vertex(64, 0), Vertex(0, 64, -1.0f)));
  CHECK(OutlineWinding(Vertex(0, 0), Vertex(64, 0), Vertex(0, 64, -0.0f)));
  CHECK_FALSE(OutlineWinding(Vertex(0, 0, -1.0f), Vertex(64, 0), Vertex(0, 64, -1.0f)));
  CHECK_FALSE(OutlineWinding(Vertex(0, 0), Vertex(32, 32), Vertex(64, 64)));  // zero area
}
