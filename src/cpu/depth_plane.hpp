// Stage 6, depth interpolation: the plane z(px, py) through the three window-space vertices, built
// in float exactly as llvmpipe's triangle setup builds its interpolants, and evaluated at integer
// pixel indices with two fused multiply-adds, then clamped to the depth range [0, 1].
#pragma once

#include "cpu/viewport_transform.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster::cpu {

struct DepthPlane {
  float a0 = 0;    // z at pixel (0, 0)
  float dzdx = 0;  // per pixel to the right
  float dzdy = 0;  // per pixel down
};

// v0, v1, v2 in the order triangle setup left them (after the winding swap).
DepthPlane MakeDepthPlane(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2);

// Unclamped plane value at pixel (px, py): fmaf(dzdy, py, fmaf(dzdx, px, a0)).
inline float PlaneDepth(const DepthPlane& p, float px, float py) {
  return std::fma(p.dzdy, py, std::fma(p.dzdx, px, p.a0));
}

// What the depth test sees: the plane value clamped to [minDepth, maxDepth] = [0, 1].
inline float DepthAt(const DepthPlane& p, int px, int py) {
  const float z = PlaneDepth(p, static_cast<float>(px), static_cast<float>(py));
  return std::min(std::max(z, 0.0f), 1.0f);
}

}  // namespace twinraster::cpu
