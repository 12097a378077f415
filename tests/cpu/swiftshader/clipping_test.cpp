// SwiftShader's clipper (cpu/swiftshader/clipping.hpp): Sutherland-Hodgman in clip space against
// only the planes asked, no guard band, new vertices made from the inside end.
#include "cpu/swiftshader/clipping.hpp"

#include "cpu/swiftshader/viewport.hpp"
#include "support/catch.hpp"

using namespace twinraster::cpu;

namespace {

ClipSpacePolygon Triangle(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
  ClipSpacePolygon p;
  p.v[0] = a, p.v[1] = b, p.v[2] = c;
  p.count = 3;
  return p;
}

}  // namespace

TEST_CASE("SwiftShader clipping: only the planes asked are clipped", "[cpu][swiftshader][clip]") {
  ClipSpacePolygon p = Triangle({0, 0, 0.5f, 1}, {2, 0, 0.5f, 1}, {0, 1, 0.5f, 1});
  REQUIRE(ClipPolygon(p, kClipLeft | kClipNear));  // the vertex outside is outside the right plane
  REQUIRE(p.count == 3);
  CHECK(p.v[1] == glm::vec4(2, 0, 0.5f, 1));
}

TEST_CASE("SwiftShader clipping: one vertex outside gives a quadrilateral, in the polygon's order",
          "[cpu][swiftshader][clip]") {
  // Against x <= w: distances 1, -1, 1, so each crossing is the midpoint of its edge.
  ClipSpacePolygon p = Triangle({0, 0, 0.5f, 1}, {2, 0, 0.5f, 1}, {0, 1, 0.5f, 1});
  REQUIRE(ClipPolygon(p, kClipRight));
  REQUIRE(p.count == 4);
  CHECK(p.v[0] == glm::vec4(0, 0, 0.5f, 1));
  CHECK(p.v[1] == glm::vec4(1, 0, 0.5f, 1));
  CHECK(p.v[2] == glm::vec4(1, 0.5f, 0.5f, 1));
  CHECK(p.v[3] == glm::vec4(0, 1, 0.5f, 1));
}

TEST_CASE("SwiftShader clipping: the crossing is computed from the inside end", "[cpu][swiftshader][clip]") {
  // Near plane z >= 0 on an edge from z = 3 (inside, w = 1) to z = -1 (outside, w = 5): the crossing is
  // (dj Vi - di Vj) / (dj - di) with i inside, every component from the same formula: w = 4.
  ClipSpacePolygon p = Triangle({0, 0, 3, 1}, {0, 0, -1, 5}, {0.5f, 0, 3, 1});
  REQUIRE(ClipPolygon(p, kClipNear));
  REQUIRE(p.count == 4);
  CHECK(p.v[1] == glm::vec4(0, 0, 0, 4));
  // The edge back in starts outside; its crossing is made from its inside end, C: (C + 3 B) / 4.
  CHECK(p.v[2] == glm::vec4(0.125f, 0, 0, 4));
}

TEST_CASE("SwiftShader clipping: a vertex on the plane is kept, a polygon outside is dropped",
          "[cpu][swiftshader][clip]") {
  ClipSpacePolygon on = Triangle({1, 0, 0.5f, 1}, {0, 1, 0.5f, 1}, {0, -1, 0.5f, 1});
  REQUIRE(ClipPolygon(on, kClipRight));
  CHECK(on.count == 3);
  ClipSpacePolygon outside = Triangle({2, 0, 0.5f, 1}, {3, 1, 0.5f, 1}, {3, -1, 0.5f, 1});
  CHECK_FALSE(ClipPolygon(outside, kClipRight));
  CHECK(outside.count == 0);
}

TEST_CASE("SwiftShader clipping: no guard band, x is cut at w itself", "[cpu][swiftshader][clip]") {
  ClipSpacePolygon p = Triangle({-4, -0.5f, 0.5f, 1}, {4, -0.5f, 0.5f, 1}, {0, 0.5f, 0.5f, 1});
  REQUIRE(ClipPolygon(p, kClipLeft | kClipRight));
  for (int i = 0; i < p.count; ++i) {
    const glm::vec4& v = p.v[static_cast<std::size_t>(i)];
    CHECK(v.x <= v.w);
    CHECK(-v.w <= v.x);
  }
  CHECK(p.count == 5);  // the triangle's tip, and two points on each side plane
}
