// Stage 6 for a Gouraud colour: perspective-correct interpolation as llvmpipe does it. Each
// channel c is set up, like depth, as a plane through c·(1/w) at the three vertices, and 1/w gets
// a plane of its own; at a pixel the colour is plane_c · (1 / plane_1/w), each plane evaluated
// with two fused multiply-adds at the pixel's integer indices.
#pragma once

#include "cpu/clipping.hpp"
#include "cpu/depth_plane.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cmath>

namespace twinraster::cpu {

struct ColourPlanes {
  std::array<DepthPlane, 3> colour_oow;  // r/w, g/w, b/w
  DepthPlane oow;                        // 1/w
};

// v0, v1, v2 in the order triangle setup left them (after the winding swap), as the depth plane.
// `fused`: evaluated with fmaf (RasterRules::fused_multiply_add), as the depth plane.
ColourPlanes MakeColourPlanes(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, bool fused = true);

// The interpolated colour at pixel (px, py), before the conversion to UNORM8.
inline glm::vec3 ColourAt(const ColourPlanes& p, float px, float py) {
  const float w = 1.0f / PlaneDepth(p.oow, px, py);
  return glm::vec3(PlaneDepth(p.colour_oow[0], px, py) * w, PlaneDepth(p.colour_oow[1], px, py) * w,
                   PlaneDepth(p.colour_oow[2], px, py) * w);
}

}  // namespace twinraster::cpu
