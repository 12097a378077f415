#include "cpu/swiftshader/planes.hpp"

#include <cstdint>

namespace twinraster::cpu {

namespace {

constexpr float kSubpixel = 1.0f / static_cast<float>(kOutlineOne);

// Subtraction of two snapped coordinates as 32-bit hardware does it: wrapping, for vertices far
// outside (or behind) the view whose coordinates saturated.
std::int32_t Minus(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) - static_cast<std::uint32_t>(b));
}
std::int32_t Plus(std::int32_t a, std::int32_t b) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(a) + static_cast<std::uint32_t>(b));
}

// Vertices 1 and 2 relative to vertex 0, in 1/16 pixel, and vertex 0 in pixels: the anchor.
struct Offsets {
  float x0, y0;
  std::int32_t x1, y1, x2, y2;
};

Offsets OffsetsOf(std::int32_t x0, std::int32_t y0, std::int32_t x1, std::int32_t y1, std::int32_t x2,
                  std::int32_t y2) {
  return {static_cast<float>(x0) * kSubpixel,
          static_cast<float>(y0) * kSubpixel,
          Minus(x1, x0),
          Minus(y1, y0),
          Minus(x2, x0),
          Minus(y2, y0)};
}

// The plane through depths z0, z1, z2 at the anchor and the two offsets (depth range [0, 1]).
AnchoredPlane DepthThrough(const Offsets& o, float z0, float z1, float z2) {
  const float fx1 = static_cast<float>(o.x1) * kSubpixel, fy1 = static_cast<float>(o.y1) * kSubpixel;
  const float fx2 = static_cast<float>(o.x2) * kSubpixel, fy2 = static_cast<float>(o.y2) * kSubpixel;
  z1 = z1 - z0;
  z2 = z2 - z0;
  constexpr float kDepthRange = 1.0f, kDepthNear = 0.0f;
  const float d = kDepthRange / (fx1 * fy2 - fx2 * fy1);  // no guard: a zero area gives inf or NaN
  return {.a = (fy2 * z1 - fy1 * z2) * d,
          .b = (fx1 * z2 - fx2 * z1) * d,
          .c = z0 * kDepthRange + kDepthNear,
          .x0 = o.x0,
          .y0 = o.y0};
}

}  // namespace

std::array<std::size_t, 3> PlaneOrder(const std::array<const SnappedVertex*, 3>& v) {
  std::array<std::size_t, 3> order = {0, 1, 2};
  // SwiftShader's Min and Max are x < y ? x : y and x > y ? x : y; each rotation step reads which
  // vertex holds the extreme before rotating.
  const auto rotate = [&order](bool once, bool back) {
    if (once) order = {order[1], order[2], order[0]};
    if (back) order = {order[2], order[0], order[1]};
  };
  const auto step = [&](auto&& value, auto&& pick) {
    const float a = value(*v[order[0]]), b = value(*v[order[1]]), c = value(*v[order[2]]);
    const float m = pick(pick(a, b), c);
    rotate(m == b, m == c);
  };
  const auto min = [](float x, float y) { return x < y ? x : y; };
  const auto max = [](float x, float y) { return x > y ? x : y; };
  step([](const SnappedVertex& s) { return s.clip.y; }, min);
  step([](const SnappedVertex& s) { return s.clip.w; }, max);
  return order;
}

AnchoredPlane TriangleDepthPlane(const SnappedVertex& v0, const SnappedVertex& v1, const SnappedVertex& v2) {
  return DepthThrough(OffsetsOf(v0.x, v0.y, v1.x, v1.y, v2.x, v2.y), v0.z, v1.z, v2.z);
}

namespace {

// m[k] = (per pixel right, per pixel down, at the anchor) of vertex k's weight: the matrix that
// turns three vertex values into the plane of value/w.
using WeightMatrix = std::array<std::array<float, 3>, 3>;

WeightMatrix Weights(const Offsets& o, const SnappedVertex& v0, const SnappedVertex& v1, const SnappedVertex& v2) {
  const float w1 = v1.clip.w, w2 = v2.clip.w, rhw0 = v0.rhw;
  const float x1 = (w1 * kSubpixel) * static_cast<float>(o.x1), y1 = (w1 * kSubpixel) * static_cast<float>(o.y1);
  const float x2 = (w2 * kSubpixel) * static_cast<float>(o.x2), y2 = (w2 * kSubpixel) * static_cast<float>(o.y2);
  const float area = x1 * y2 - x2 * y1;
  WeightMatrix m = {{{0, 0, rhw0}, {0, 0, 0}, {0, 0, 0}}};
  if (area == 0.0f) return m;
  const float inverse = 1.0f / area, d = inverse * rhw0;
  m[0][0] = (y1 * w2 - y2 * w1) * d;
  m[0][1] = (x2 * w1 - x1 * w2) * d;
  m[1][0] = y2 * inverse;
  m[1][1] = -x2 * inverse;
  m[2][0] = -y1 * inverse;
  m[2][1] = x1 * inverse;
  return m;
}

// The plane of values i0, i1, i2 at the three vertices, divided by w.
AnchoredPlane PlaneOf(const WeightMatrix& m, const Offsets& o, float i0, float i1, float i2) {
  return {.a = (i0 * m[0][0] + i1 * m[1][0]) + i2 * m[2][0],
          .b = (i0 * m[0][1] + i1 * m[1][1]) + i2 * m[2][1],
          .c = (i0 * m[0][2] + i1 * m[1][2]) + i2 * m[2][2],
          .x0 = o.x0,
          .y0 = o.y0};
}

}  // namespace

AnchoredColourPlanes TriangleColourPlanes(const SnappedVertex& v0, const SnappedVertex& v1, const SnappedVertex& v2,
                                          const std::array<glm::vec3, 3>& colours) {
  const Offsets o = OffsetsOf(v0.x, v0.y, v1.x, v1.y, v2.x, v2.y);
  const WeightMatrix m = Weights(o, v0, v1, v2);
  AnchoredColourPlanes p;
  for (int k = 0; k < 3; ++k) {
    p.colour_oow[static_cast<std::size_t>(k)] = PlaneOf(m, o, colours[0][k], colours[1][k], colours[2][k]);
  }
  // The 1/w plane: the weights summed, the matrix applied to (1, 1, 1), each product exact.
  p.oow = AnchoredPlane{.a = (m[0][0] + m[1][0]) + m[2][0],
                        .b = (m[0][1] + m[1][1]) + m[2][1],
                        .c = (m[0][2] + m[1][2]) + m[2][2],
                        .x0 = o.x0,
                        .y0 = o.y0};
  return p;
}

AnchoredPlane LineDepthPlane(const SnappedVertex& a, const SnappedVertex& b) {
  const std::int32_t x2 = Minus(Plus(b.x, b.y), a.y), y2 = Minus(Plus(b.y, a.x), b.x);
  return DepthThrough(OffsetsOf(a.x, a.y, b.x, b.y, x2, y2), a.z, b.z, b.z);
}

}  // namespace twinraster::cpu
