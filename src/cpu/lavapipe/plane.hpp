// Stage 6, depth interpolation: the plane z(px, py) through the three window-space vertices, built
// in float exactly as llvmpipe's triangle setup builds its interpolants, and evaluated at integer
// pixel indices with two fused multiply-adds (or, on a lavapipe without FMA, two multiplies and two
// adds), then clamped to the depth range [0, 1].
#pragma once

#include "cpu/lavapipe/viewport.hpp"

#include <cmath>

namespace twinraster::cpu {

struct DepthPlane {
  float a0 = 0;       // z at pixel (0, 0)
  float dzdx = 0;     // per pixel to the right
  float dzdy = 0;     // per pixel down
  bool fused = true;  // evaluated with fmaf (RasterRules::fused_multiply_add)
};

// v0, v1, v2 in the order triangle setup left them (after the winding swap).
DepthPlane MakeDepthPlane(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2);
// The same plane through values a0, a1, a2 at the three vertices instead of their z: llvmpipe
// sets up every linearly interpolated input this way.
DepthPlane MakePlane(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2, float a0, float a1, float a2);

// Unclamped plane value at pixel (px, py): fmaf(dzdy, py, fmaf(dzdx, px, a0)), or the same with
// each multiply and add rounded on its own.
inline float PlaneDepth(const DepthPlane& p, float px, float py) {
  if (!p.fused) return p.dzdy * py + (p.dzdx * px + p.a0);
  return std::fma(p.dzdy, py, std::fma(p.dzdx, px, p.a0));
}

// The clamp to the depth range [minDepth, maxDepth] = [0, 1] as llvmpipe's code does it with SSE:
// min(z, 1) then max(z, 0), where min(a, b) = a < b ? a : b and max(a, b) = a > b ? a : b. So a NaN
// (from a triangle whose float area is 0 although its snapped area is not) becomes 1.0, and -0.0
// becomes +0.0.
inline float ClampDepth(float z) {
  z = z < 1.0f ? z : 1.0f;
  return z > 0.0f ? z : 0.0f;
}

// What the depth test sees at pixel (px, py).
inline float DepthAt(const DepthPlane& p, int px, int py) {
  return ClampDepth(PlaneDepth(p, static_cast<float>(px), static_cast<float>(py)));
}

}  // namespace twinraster::cpu
