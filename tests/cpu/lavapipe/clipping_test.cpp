// Stage 2: outcodes, trivial accept/reject, Sutherland-Hodgman against the Vulkan view volume.
#include "cpu/lavapipe/clipping.hpp"

#include "cpu/chunk_assembly.hpp"
#include "support/catch.hpp"

#include <cmath>
#include <vector>

using namespace twinraster::cpu;

namespace {

const ViewportState kVp = MakeViewport(100, 100);

ClipVertex Vertex(float x, float y, float z, float w) {
  ClipVertex v;
  v.clip = glm::vec4(x, y, z, w);
  v.window = ViewportTransformShader(kVp, v.clip);
  return v;
}

ShadedVertex Shaded(const ClipVertex& v) { return {v, Outcode(v.clip)}; }

bool SameBits(const glm::vec4& a, const glm::vec4& b) {
  for (int k = 0; k < 4; ++k) {
    if (std::signbit(a[k]) != std::signbit(b[k]) || !(a[k] == b[k])) return false;
  }
  return true;
}

std::vector<TriangleSetup> Assemble(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
  const ShadedVertex sa = Shaded(a), sb = Shaded(b), sc = Shaded(c);
  std::vector<TriangleSetup> out;
  AssembleTriangle({&sa, &sb, &sc}, 0xffffffffu, kVp, DrawRegion(kVp, 100, 100), out);
  return out;
}

}  // namespace

TEST_CASE("outcodes: one bit per plane of -w<=x<=w, -w<=y<=w, 0<=z<=w", "[cpu][clip]") {
  CHECK(Outcode({0.0f, 0.0f, 0.5f, 1.0f}) == 0u);
  CHECK(Outcode({1.0f, -1.0f, 1.0f, 1.0f}) == 0u);  // on the planes is inside
  CHECK(Outcode({0.0f, 0.0f, 0.0f, 1.0f}) == 0u);
  CHECK(Outcode({1.5f, 0.0f, 0.5f, 1.0f}) == kOutsideXMax);
  CHECK(Outcode({-1.5f, 0.0f, 0.5f, 1.0f}) == kOutsideXMin);
  CHECK(Outcode({0.0f, 1.5f, 0.5f, 1.0f}) == kOutsideYMax);
  CHECK(Outcode({0.0f, -1.5f, 0.5f, 1.0f}) == kOutsideYMin);
  CHECK(Outcode({0.0f, 0.0f, -0.5f, 1.0f}) == kOutsideZMin);
  CHECK(Outcode({0.0f, 0.0f, 1.5f, 1.0f}) == kOutsideZMax);
  // Behind the camera (w < 0) a point is outside both x planes and both y planes at once.
  CHECK(Outcode({0.0f, 0.0f, -2.0f, -1.0f}) ==
        (kOutsideXMax | kOutsideXMin | kOutsideYMax | kOutsideYMin | kOutsideZMin));
}

TEST_CASE("plane distances: dot product with the plane vector", "[cpu][clip]") {
  const glm::vec4 p(0.25f, -0.5f, 0.75f, 2.0f);
  CHECK(PlaneDistance(p, 0) == 1.75f);  // w - x
  CHECK(PlaneDistance(p, 1) == 2.25f);  // x + w
  CHECK(PlaneDistance(p, 2) == 2.5f);   // w - y
  CHECK(PlaneDistance(p, 3) == 1.5f);   // y + w
  CHECK(PlaneDistance(p, 4) == 0.75f);  // z
  CHECK(PlaneDistance(p, 5) == 1.25f);  // w - z
}

TEST_CASE("a triangle fully inside is drawn unchanged", "[cpu][clip]") {
  const ClipVertex a = Vertex(-0.5f, -0.5f, 0.5f, 1.0f), b = Vertex(0.5f, -0.5f, 0.5f, 1.0f),
                   c = Vertex(0.0f, 0.5f, 0.5f, 1.0f);
  ClippedPolygon polygon;
  ClipTriangle(a, b, c, 0u, kVp, polygon);  // no plane to clip against
  REQUIRE(polygon.count == 3);
  CHECK(SameBits(polygon.v[0].clip, a.clip));
  CHECK(SameBits(polygon.v[1].clip, b.clip));
  CHECK(SameBits(polygon.v[2].clip, c.clip));

  const std::vector<TriangleSetup> drawn = Assemble(a, b, c);
  REQUIRE(drawn.size() == 1);
  TriangleSetup direct;
  REQUIRE(SetUpTriangle(a.window, b.window, c.window, DrawRegion(kVp, 100, 100), direct));
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(Edges(drawn[0])[i].c == Edges(direct)[i].c);
    CHECK(Edges(drawn[0])[i].dcdx == Edges(direct)[i].dcdx);
    CHECK(Edges(drawn[0])[i].dcdy == Edges(direct)[i].dcdy);
  }
}

TEST_CASE("a triangle fully outside is rejected", "[cpu][clip]") {
  // All three beyond x = w: trivially rejected.
  CHECK(Assemble(Vertex(1.5f, 0.0f, 0.5f, 1.0f), Vertex(2.0f, 0.5f, 0.5f, 1.0f), Vertex(1.2f, -0.5f, 0.5f, 1.0f))
            .empty());
  // No shared bit (one beyond x = w, one beyond y = w), yet outside the corner x, y <= w: clipping
  // against x = w leaves a piece with y >= 1.4 that the y = w plane removes.
  const ClipVertex a = Vertex(1.5f, 0.9f, 0.5f, 1.0f), b = Vertex(0.9f, 1.5f, 0.5f, 1.0f),
                   c = Vertex(1.5f, 1.5f, 0.5f, 1.0f);
  ClippedPolygon polygon;
  ClipTriangle(a, b, c, Outcode(a.clip) | Outcode(b.clip) | Outcode(c.clip), kVp, polygon);
  CHECK(polygon.count == 0);
  CHECK(Assemble(a, b, c).empty());
}

TEST_CASE("a triangle straddling the near plane z = 0 becomes a quadrilateral", "[cpu][clip]") {
  // v0 is in front of the near plane (z < 0), v1 and v2 behind it; distances to z >= 0 are
  // -0.5, 0.5, 0.5. Both crossings are ties (|d| equal), so both new vertices start from the inside
  // vertex, with t = 0.5:
  //   v0 -> v1 (entering): v1 + 0.5 (v0 - v1) = (0, -0.5, 0, 1)
  //   v2 -> v0 (leaving):  v2 + 0.5 (v0 - v2) = (-0.25, 0, 0, 1)
  // Output order: new(v0,v1), v1, v2, new(v2,v0), drawn as the fan (p0,p1,p2), (p0,p2,p3).
  const ClipVertex v0 = Vertex(-0.5f, -0.5f, -0.5f, 1.0f), v1 = Vertex(0.5f, -0.5f, 0.5f, 1.0f),
                   v2 = Vertex(0.0f, 0.5f, 0.5f, 1.0f);
  ClippedPolygon polygon;
  ClipTriangle(v0, v1, v2, kOutsideZMin, kVp, polygon);
  REQUIRE(polygon.count == 4);
  CHECK(SameBits(polygon.v[0].clip, {0.0f, -0.5f, 0.0f, 1.0f}));
  CHECK(SameBits(polygon.v[1].clip, v1.clip));
  CHECK(SameBits(polygon.v[2].clip, v2.clip));
  CHECK(SameBits(polygon.v[3].clip, {-0.25f, 0.0f, 0.0f, 1.0f}));
  // Original vertices keep their shader (fma) window position; new ones get the plain one.
  CHECK(polygon.v[1].window.x == v1.window.x);
  CHECK(polygon.v[0].window.x == 50.0f);
  CHECK(polygon.v[0].window.y == 25.0f);
  CHECK(polygon.v[3].window.x == 37.5f);
  CHECK(polygon.v[3].window.y == 50.0f);
  CHECK(Assemble(v0, v1, v2).size() == 2);
}

TEST_CASE("new vertices start from the endpoint nearer the plane, whichever way the edge runs", "[cpu][clip]") {
  // Plane z >= 0. Inside vertex at distance 1, outside at -3: the inside one is nearer, t = 1/4.
  // From it: 0.1f + 0.25 (0.9f - 0.1f) = 0x1.333332p-2; from the other end the float result would
  // be 0x1.333334p-2.
  const ClipVertex in = Vertex(0.1f, 0.0f, 1.0f, 1.0f), out = Vertex(0.9f, 0.0f, -3.0f, 1.0f);
  const ClipVertex leaving = IntersectEdge(in, 1.0f, out, -3.0f, kVp);
  const ClipVertex entering = IntersectEdge(out, -3.0f, in, 1.0f, kVp);
  CHECK(leaving.clip.x == 0x1.333332p-2f);
  CHECK(leaving.clip.z == 0.0f);
  CHECK(leaving.clip.w == 1.0f);
  CHECK(SameBits(entering.clip, leaving.clip));
  volatile float t = 0.75f;
  CHECK(0.9f + t * (0.1f - 0.9f) == 0x1.333334p-2f);  // the far-end formula differs indeed

  // Outside vertex nearer (distance -1 against 3): it is the base.
  const ClipVertex in3 = Vertex(0.9f, 0.0f, 3.0f, 1.0f), out1 = Vertex(0.1f, 0.0f, -1.0f, 1.0f);
  CHECK(IntersectEdge(in3, 3.0f, out1, -1.0f, kVp).clip.x == 0x1.333332p-2f);
  CHECK(IntersectEdge(out1, -1.0f, in3, 3.0f, kVp).clip.x == 0x1.333332p-2f);

  // A tie (distances 1 and -1) starts from the inside vertex: 0.1f + 0.5 (0.3f - 0.1f) =
  // 0x1.99999cp-3, where starting from 0.3f would give 0x1.99999ap-3.
  const ClipVertex in_tie = Vertex(0.1f, 0.0f, 1.0f, 1.0f), out_tie = Vertex(0.3f, 0.0f, -1.0f, 1.0f);
  CHECK(IntersectEdge(in_tie, 1.0f, out_tie, -1.0f, kVp).clip.x == 0x1.99999cp-3f);
  CHECK(IntersectEdge(out_tie, -1.0f, in_tie, 1.0f, kVp).clip.x == 0x1.99999cp-3f);
}

TEST_CASE("triangles behind the camera (w < 0)", "[cpu][clip]") {
  // Entirely behind: every vertex has z < 0, so the triangle is rejected without clipping.
  CHECK(Assemble(Vertex(0.5f, 0.5f, -1.2f, -1.0f), Vertex(-0.5f, 0.5f, -1.2f, -1.0f), Vertex(0.0f, -0.5f, -2.4f, -2.0f))
            .empty());

  // One vertex behind: x and y planes first (all four are set by the w < 0 vertex), then z >= 0.
  // The result is the triangle cut by z = 0: v1, v2 and two vertices near (-0.2, 0.2, 0, 0.6) and
  // (0.4, -0.2, 0, 0.6), where the edges from v0 (at 80% of their length) cross z = 0.
  const ClipVertex v0 = Vertex(0.0f, 0.0f, -2.0f, -1.0f), v1 = Vertex(-0.25f, 0.25f, 0.5f, 1.0f),
                   v2 = Vertex(0.5f, -0.25f, 0.5f, 1.0f);
  ClippedPolygon polygon;
  ClipTriangle(v0, v1, v2, Outcode(v0.clip) | Outcode(v1.clip) | Outcode(v2.clip), kVp, polygon);
  REQUIRE(polygon.count == 4);
  int originals = 0;
  for (int i = 0; i < polygon.count; ++i) {
    const glm::vec4& p = polygon.v[static_cast<std::size_t>(i)].clip;
    CHECK(p.w > 0.0f);
    if (SameBits(p, v1.clip) || SameBits(p, v2.clip)) {
      ++originals;
      continue;
    }
    CHECK(std::fabs(p.z) <= 1e-6f);
    CHECK(p.w == Approx(0.6f).margin(1e-6));
    const bool on_v0v1 = std::fabs(p.x + 0.2f) <= 1e-6f && std::fabs(p.y - 0.2f) <= 1e-6f;
    const bool on_v0v2 = std::fabs(p.x - 0.4f) <= 1e-6f && std::fabs(p.y + 0.2f) <= 1e-6f;
    CHECK((on_v0v1 || on_v0v2));
  }
  CHECK(originals == 2);
  CHECK(Assemble(v0, v1, v2).size() == 2);
}

TEST_CASE("an infinite distance drops the whole triangle", "[cpu][clip]") {
  const float inf = INFINITY;
  const ClipVertex a = Vertex(inf, 0.0f, 0.5f, 1.0f), b = Vertex(0.5f, -0.5f, 0.5f, 1.0f),
                   c = Vertex(0.0f, 0.5f, 0.5f, 1.0f);
  ClippedPolygon polygon;
  ClipTriangle(a, b, c, Outcode(a.clip), kVp, polygon);  // distance w - x = -inf
  CHECK(polygon.count == 0);
}
