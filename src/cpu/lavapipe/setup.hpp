// Stages 4 and 5, triangle setup (Vulkan spec "Polygon Rasterization", "Rasterization Rules"):
//  - Snapping: window x, y to fixed point with 8 subpixel bits, measured from the pixel centre:
//    X = round_half_even((xw - 0.5f) * 256.0f), so pixel (px, py)'s centre is (px * 256, py * 256).
//  - Twice the signed area in 64-bit: (X0-X1)(Y2-Y0) - (X2-X0)(Y0-Y1). Zero: nothing is drawn.
//    Negative: vertices 1 and 2 are swapped (vertex 0, the provoking vertex, stays).
//  - One edge function per edge i -> j (j = i + 1 mod 3): dcdx = Yi - Yj, dcdy = Xi - Xj,
//    c = dcdx * Xi - dcdy * Yi, plus 1 for a left edge (dcdx < 0) or a top edge (dcdx == 0 and
//    dcdy > 0): the top-left rule, turning "on the edge" into "inside" for those edges only.
//    Pixel (px, py) is covered when c + dcdy * (py * 256) - dcdx * (px * 256) > 0 for all three.
//  - The bounding box of the snapped vertices (as llvmpipe rounds it) ∩ the draw region.
// The setup keeps the snapped vertices; the edge functions follow from them (Edges).
#pragma once

#include "cpu/lavapipe/plane.hpp"
#include "cpu/lavapipe/viewport.hpp"

#include <array>
#include <cstdint>

namespace twinraster::cpu {

constexpr int kSubpixelBits = 8;
constexpr std::int32_t kSubpixelOne = 1 << kSubpixelBits;

// round_half_even((w - 0.5f) * 256.0f) as SSE's cvtps2dq does it: out of range or NaN gives
// INT32_MIN.
std::int32_t SnapToSubpixel(float window_coord);
// The same as Mesa 22.3.6 snaps where it is built without SSE (aarch64): util_iround's C form,
// (int)(f + 0.5f) or (int)(f - 0.5f), half away from zero (RasterRules::triangles_round_half_away).
std::int32_t SnapToSubpixelHalfAway(float window_coord);

struct EdgeFunction {
  std::int64_t c = 0;     // with the top-left bias
  std::int64_t dcdx = 0;  // Yi - Yj
  std::int64_t dcdy = 0;  // Xi - Xj
};

// Edge function value at the centre of pixel (px, py); > 0 is inside.
inline std::int64_t EdgeAt(const EdgeFunction& e, int px, int py) {
  return e.c + e.dcdy * (std::int64_t{py} * kSubpixelOne) - e.dcdx * (std::int64_t{px} * kSubpixelOne);
}

inline EdgeFunction MakeEdge(std::int64_t xi, std::int64_t yi, std::int64_t xj, std::int64_t yj) {
  EdgeFunction e;
  e.dcdx = yi - yj;
  e.dcdy = xi - xj;
  // Wrapping, as the machine's 64-bit multiply does: snapped coordinates of a NaN or a vertex
  // far out of range (a broken scene) can reach 2^32, whose products overflow; in range it is exact.
  const auto wrap = [](std::int64_t a, std::int64_t b) {
    return static_cast<std::uint64_t>(a) * static_cast<std::uint64_t>(b);
  };
  e.c = static_cast<std::int64_t>(wrap(e.dcdx, xi) - wrap(e.dcdy, yi));
  const bool left_edge = e.dcdx < 0;
  const bool top_edge = e.dcdx == 0 && e.dcdy > 0;
  if (left_edge || top_edge) e.c += 1;
  return e;
}

// What rasterization needs of one triangle, kept small (64 bytes) because a million cubes set up
// twelve million of them: the edge functions are not stored but rebuilt from the snapped vertices
// where a triangle is drawn (Edges), which costs less than moving them through memory.
struct TriangleSetup {
  std::array<std::int32_t, 3> x{}, y{};  // snapped vertices, in post-swap order
  PixelRect bounds;                      // pixels that may be covered, inside the draw region
  DepthPlane depth;                      // from the vertices in post-swap order
  std::uint32_t colour = 0;              // RGBA8, or for a smooth triangle the index of its ColourPlanes
  bool swapped = false;                  // the snapped area was negative, so vertices 1 and 2 were swapped
  bool smooth = false;                   // Gouraud: the colour is interpolated (planes.hpp)
};

// The three edge functions, edge i running from vertex i to vertex i + 1 mod 3.
inline std::array<EdgeFunction, 3> Edges(const TriangleSetup& t) {
  return {MakeEdge(t.x[0], t.y[0], t.x[1], t.y[1]), MakeEdge(t.x[1], t.y[1], t.x[2], t.y[2]),
          MakeEdge(t.x[2], t.y[2], t.x[0], t.y[0])};
}

// False when the triangle covers nothing for sure (zero area, or its box misses `region`).
// `rules`: how the vertices snap (triangles_round_half_away).
bool SetUpTriangle(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2, const PixelRect& region,
                   TriangleSetup& out, const RasterRules& rules = {});

// The coverage test for one pixel, bounds included.
bool Covers(const TriangleSetup& t, int px, int py);

}  // namespace twinraster::cpu
