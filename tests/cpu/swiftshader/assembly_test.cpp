// SwiftShader's primitive assembly (cpu/swiftshader/assembly.hpp): a triangle is one polygon,
// clipped or not, with the original triangle's planes; a wireframe triangle is three 1-pixel-wide
// quads; a triangle with a coordinate not finite, or outside one plane, draws nothing.
#include "cpu/swiftshader/assembly.hpp"

#include "cpu/swiftshader/planes.hpp"
#include "support/catch.hpp"

#include <limits>
#include <vector>

using namespace twinraster::cpu;

namespace {

// A 64 x 64 viewport: wxf = 512, x0xf = 504, so pixel centre px is at clip x (16 px - 504) / 512
// with w = 1, every value exact.
const SnapViewport kVp = MakeSnapViewport(64, 64);

float ClipOf(float pixel) { return (16.0f * pixel - 504.0f) / 512.0f; }

SnappedVertex Pixel(float px, float py, float z = 0.5f) {
  return SnapShaderVertex({ClipOf(px), ClipOf(py), z, 1.0f}, kVp);
}

struct Output {
  std::vector<OutlineSetup> setups;
  std::vector<SnappedPoint> points;
  std::vector<AnchoredColourPlanes> planes;
  OutlineOutput Out() { return {setups, points, planes}; }
};

}  // namespace

TEST_CASE("SwiftShader assembly: a triangle inside is one set-up of its snapped vertices",
          "[cpu][swiftshader][assembly]") {
  const SnappedVertex a = Pixel(10, 10), b = Pixel(10, 20), c = Pixel(20, 10);
  Output out;
  AssembleOutlineTriangle({&a, &b, &c}, 0x11223344u, kVp, out.Out());
  REQUIRE(out.setups.size() == 1);
  const OutlineSetup& s = out.setups[0];
  CHECK(s.colour == 0x11223344u);
  CHECK_FALSE(s.smooth);
  CHECK(s.d == OutlineWinding(a, b, c));
  REQUIRE(s.count == 3);
  CHECK(out.points[s.first].x == 160);
  CHECK(out.points[s.first + 1].y == 320);
  CHECK(out.points[s.first + 2].x == 320);
  CHECK(s.bounds.x0 == 10);
  CHECK(s.bounds.x1 == 19);  // centre 20 is on the right end: ceil(320 / 16) - 1
  CHECK(s.bounds.y0 == 10);
  CHECK(s.bounds.y1 == 19);
  // The depth plane is anchored at the vertex PlaneOrder puts first: a and c share the smallest clip
  // y, and the rotation stops at the last of them, c.
  CHECK(PlaneOrder({&a, &b, &c}) == std::array<std::size_t, 3>{2, 0, 1});
  CHECK(s.depth.x0 == 20.0f);
  CHECK(s.depth.y0 == 10.0f);
}

TEST_CASE("SwiftShader assembly: dropped when outside one plane or not finite", "[cpu][swiftshader][assembly]") {
  Output out;
  const SnappedVertex a = Pixel(70, 10), b = Pixel(80, 10), c = Pixel(75, 20);  // right of x = 64
  AssembleOutlineTriangle({&a, &b, &c}, 1, kVp, out.Out());
  const SnappedVertex nan = SnapShaderVertex({std::numeric_limits<float>::quiet_NaN(), 0, 0.5f, 1}, kVp);
  const SnappedVertex d = Pixel(10, 10), e = Pixel(20, 10);
  AssembleOutlineTriangle({&d, &e, &nan}, 1, kVp, out.Out());
  CHECK(out.setups.empty());
  CHECK(out.points.empty());
}

TEST_CASE("SwiftShader assembly: a clipped triangle is one polygon with the original's depth plane",
          "[cpu][swiftshader][assembly]") {
  // Across the right edge (window x = 64): one vertex out, so the polygon has four points, not a fan.
  const SnappedVertex a = Pixel(50, 10, 0.25f), b = Pixel(50, 30, 0.5f), c = Pixel(90, 20, 0.75f);
  Output out;
  AssembleOutlineTriangle({&a, &b, &c}, 7, kVp, out.Out());
  REQUIRE(out.setups.size() == 1);
  const OutlineSetup& s = out.setups[0];
  CHECK(s.count == 4);
  CHECK(s.bounds.x1 == 63);
  const std::array<std::size_t, 3> k = PlaneOrder({&a, &b, &c});
  const std::array<const SnappedVertex*, 3> v = {&a, &b, &c};
  const AnchoredPlane expected = TriangleDepthPlane(*v[k[0]], *v[k[1]], *v[k[2]]);
  CHECK(s.depth.a == expected.a);
  CHECK(s.depth.b == expected.b);
  CHECK(s.depth.c == expected.c);
}

TEST_CASE("SwiftShader assembly: a smooth triangle appends its colour planes and indexes them",
          "[cpu][swiftshader][assembly]") {
  const SnappedVertex a = Pixel(10, 10), b = Pixel(10, 20), c = Pixel(20, 10);
  Output out;
  const std::array<glm::vec3, 3> colours = {glm::vec3(1, 0, 0), glm::vec3(0, 1, 0), glm::vec3(0, 0, 1)};
  AssembleOutlineSmooth({&a, &b, &c}, colours, kVp, out.Out());
  AssembleOutlineSmooth({&a, &b, &c}, colours, kVp, out.Out());
  REQUIRE(out.setups.size() == 2);
  REQUIRE(out.planes.size() == 2);
  CHECK(out.setups[0].smooth);
  CHECK(out.setups[0].colour == 0);
  CHECK(out.setups[1].colour == 1);
  // At vertex a (its pixel centre) the colour is a's, whichever vertex anchors the planes.
  const glm::vec3 at_a = ColourAt(out.planes[0], 10.0f, 10.0f);
  CHECK(at_a.x == Approx(1.0).margin(1e-6));
  CHECK(at_a.y == Approx(0.0).margin(1e-6));
}

TEST_CASE("SwiftShader assembly: a wireframe triangle is three quads, one pixel wide", "[cpu][swiftshader][assembly]") {
  const SnappedVertex a = Pixel(10, 10), b = Pixel(30, 10), c = Pixel(10, 30);
  Output out;
  AssembleOutlineWireframe({&a, &b, &c}, 9, kVp, out.Out());
  REQUIRE(out.setups.size() == 3);
  for (const OutlineSetup& s : out.setups) {
    CHECK(s.count == 4);
    CHECK(s.d);
    CHECK(s.colour == 9u);
  }
  // a -> b, horizontal along row 10: half a pixel either side covers row 10 alone, no end caps.
  const OutlineSetup& ab = out.setups[0];
  CHECK(ab.bounds.y0 == 10);
  CHECK(ab.bounds.y1 == 10);
  CHECK(ab.bounds.x0 == 10);
  CHECK(ab.bounds.x1 == 29);
  const Span row = OutlineSpan(out.points.data() + ab.first, ab.count, ab.d, 64, 10);
  CHECK(row.begin == 10);
  CHECK(row.end == 30);
  // c -> a, vertical along column 10: column 10 alone.
  const OutlineSetup& ca = out.setups[2];
  CHECK(ca.bounds.x0 == 10);
  CHECK(ca.bounds.x1 == 10);
  // Depth along a line: the line's own plane, none across it.
  CHECK(ab.depth.b == 0.0f);
}
