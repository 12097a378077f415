// SwiftShader's planes (cpu/swiftshader/planes.hpp, plane.hpp): built in float from the snapped
// vertices of the original triangle, anchored at its vertex 0 after the rotations, evaluated
// y term first and clamped max before min.
#include "cpu/swiftshader/planes.hpp"

#include "cpu/swiftshader/plane.hpp"
#include "support/catch.hpp"

#include <cmath>
#include <limits>

using namespace twinraster::cpu;

namespace {

// A vertex snapped at pixel centre (px, py) (x = 16 px), at depth z, with clip y and w as given.
SnappedVertex At(int px, int py, float z, float clip_y = 0.0f, float w = 1.0f) {
  SnappedVertex v;
  v.x = 16 * px;
  v.y = 16 * py;
  v.z = z;
  v.clip = glm::vec4(0.0f, clip_y, z * w, w);
  v.rhw = 1.0f / w;
  return v;
}

}  // namespace

TEST_CASE("SwiftShader plane order: vertex 0 the smallest clip y, then the largest w", "[cpu][swiftshader][planes]") {
  const SnappedVertex a = At(0, 0, 0, 0.5f), b = At(1, 0, 0, -0.5f), c = At(0, 1, 0, 0.2f);
  // Smallest y is b: rotated to (b, c, a); the w are equal, so the second step keeps it.
  CHECK(PlaneOrder({&a, &b, &c}) == std::array<std::size_t, 3>{1, 2, 0});
  // With c's w the largest, the second step rotates c to the front: (c, a, b). Rotations keep the winding.
  const SnappedVertex far_c = At(0, 1, 0, 0.2f, 2.0f);
  CHECK(PlaneOrder({&a, &b, &far_c}) == std::array<std::size_t, 3>{2, 0, 1});
}

TEST_CASE("SwiftShader depth plane: per-pixel slopes, anchored at vertex 0", "[cpu][swiftshader][planes]") {
  // z = 0.5 at (2, 3), 0.75 one pixel right, 0.25 one pixel down: slopes 0.25 and -0.25.
  const AnchoredPlane p = TriangleDepthPlane(At(2, 3, 0.5f), At(3, 3, 0.75f), At(2, 4, 0.25f));
  CHECK(p.a == 0.25f);
  CHECK(p.b == -0.25f);
  CHECK(p.c == 0.5f);
  CHECK(p.x0 == 2.0f);
  CHECK(p.y0 == 3.0f);
  CHECK(PlaneDepth(p, 6.0f, 1.0f) == 4 * 0.25f + (0.5f + -2 * -0.25f));
  CHECK(DepthAt(p, 6, 1) == 1.0f);  // 2.0, clamped
  CHECK(DepthAt(p, 2, 6) == 0.0f);  // -0.25, clamped
  CHECK(DepthAt(p, 3, 4) == 0.5f);  // 0.25 - 0.25 + 0.5
}

TEST_CASE("SwiftShader depth: evaluated y term first, clamped max before min", "[cpu][swiftshader][planes]") {
  // c + yf * b first: with c = 1, b = 2^-24 and a = -1 at xf = 1, yf = 1, the y term is lost to
  // rounding (1 + 2^-24 rounds to 1), so the result is exactly 0; the x term first would keep it.
  const AnchoredPlane p{.a = -1.0f, .b = std::ldexp(1.0f, -24), .c = 1.0f, .x0 = 0.0f, .y0 = 0.0f};
  CHECK(PlaneDepth(p, 1.0f, 1.0f) == 0.0f);
  CHECK((1.0f * p.a + p.c) + 1.0f * p.b != 0.0f);
  CHECK(ClampDepthMaxFirst(std::numeric_limits<float>::quiet_NaN()) == 0.0f);  // lavapipe's order gives 1
  CHECK_FALSE(std::signbit(ClampDepthMaxFirst(-0.0f)));
  CHECK(ClampDepthMaxFirst(1.5f) == 1.0f);
}

TEST_CASE("SwiftShader line depth: along the line only, none across", "[cpu][swiftshader][planes]") {
  // From (1, 1) at 0.25 to (3, 1) at 0.75: 0.25 per pixel right, nothing down.
  const AnchoredPlane p = LineDepthPlane(At(1, 1, 0.25f), At(3, 1, 0.75f));
  CHECK(p.a == 0.25f);
  CHECK(p.b == 0.0f);
  CHECK(p.c == 0.25f);
  CHECK(p.x0 == 1.0f);
  CHECK(p.y0 == 1.0f);
  // A vertical line: depth changes down it, not across.
  const AnchoredPlane q = LineDepthPlane(At(1, 1, 0.25f), At(1, 5, 0.75f));
  CHECK(q.a == 0.0f);
  CHECK(q.b == 0.125f);
}

TEST_CASE("SwiftShader colour planes: a constant colour stays constant, a linear one is its slope",
          "[cpu][swiftshader][planes]") {
  const SnappedVertex v0 = At(2, 3, 0.5f), v1 = At(3, 3, 0.5f), v2 = At(2, 4, 0.5f);
  const AnchoredColourPlanes flat = TriangleColourPlanes(
      v0, v1, v2, {glm::vec3(0.25f, 0.5f, 1.0f), glm::vec3(0.25f, 0.5f, 1.0f), glm::vec3(0.25f, 0.5f, 1.0f)});
  CHECK(flat.oow.c == 1.0f);  // w = 1 everywhere: 1/w is 1, flat
  CHECK(flat.oow.a == 0.0f);
  CHECK(flat.oow.b == 0.0f);
  CHECK(ColourAt(flat, 7.0f, 9.0f) == glm::vec3(0.25f, 0.5f, 1.0f));
  // Red 0 at v0, 1 one pixel right, 0 one pixel down: a = 1, b = 0.
  const AnchoredColourPlanes ramp =
      TriangleColourPlanes(v0, v1, v2, {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f)});
  CHECK(ramp.colour_oow[0].a == 1.0f);
  CHECK(ramp.colour_oow[0].b == 0.0f);
  CHECK(ramp.colour_oow[0].c == 0.0f);
  CHECK(ColourAt(ramp, 2.5f, 3.0f).x == 0.5f);
}

TEST_CASE("SwiftShader colour planes are perspective-correct", "[cpu][swiftshader][planes]") {
  // v1 twice as far (w = 2): halfway across the screen, the colour is nearer v0's, as 1/w weighs it.
  const SnappedVertex v0 = At(0, 0, 0.5f), v1 = At(2, 0, 0.5f, 0.0f, 2.0f), v2 = At(0, 2, 0.5f);
  const AnchoredColourPlanes p =
      TriangleColourPlanes(v0, v1, v2, {glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(0.0f)});
  // At (1, 0): c/w interpolates linearly to 0.25, 1/w to 0.75, so the colour is 1/3.
  CHECK(ColourAt(p, 1.0f, 0.0f).x == Approx(1.0 / 3.0).epsilon(1e-6));
  CHECK(ColourAt(p, 0.0f, 0.0f).x == 0.0f);
  CHECK(ColourAt(p, 2.0f, 0.0f).x == Approx(1.0).epsilon(1e-6));
}
