// Stage 6 for a Gouraud colour: perspective-correct interpolation. Each channel c is set up, like
// depth, as a plane through c·(1/w) at the three vertices, and 1/w gets a plane of its own; at a
// pixel the colour is plane_c · (1 / plane_1/w). This file builds lavapipe's planes, evaluated with
// two fused multiply-adds at the pixel's integer indices; SwiftShader's are built from its snapped
// vertices weighted by w (swiftshader_planes.hpp) and evaluated from their anchor.
#pragma once

#include "cpu/anchored_plane.hpp"
#include "cpu/clipping.hpp"
#include "cpu/depth_plane.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cmath>

namespace twinraster::cpu {

// Perspective-correct colour as two kinds of plane: one per channel through c·(1/w), and one
// through 1/w. `Plane` is how a plane is evaluated: lavapipe's DepthPlane or SwiftShader's
// AnchoredPlane.
template <class Plane>
struct ColourPlanesOf {
  std::array<Plane, 3> colour_oow;  // r/w, g/w, b/w
  Plane oow;                        // 1/w
};
using ColourPlanes = ColourPlanesOf<DepthPlane>;
using AnchoredColourPlanes = ColourPlanesOf<AnchoredPlane>;

// v0, v1, v2 in the order triangle setup left them (after the winding swap), as the depth plane.
// `fused`: evaluated with fmaf (RasterRules::fused_multiply_add), as the depth plane.
ColourPlanes MakeColourPlanes(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, bool fused = true);

// The interpolated colour at pixel (px, py), before the conversion to UNORM8: one division, then
// a multiply per channel, as both devices do it.
template <class Plane>
glm::vec3 ColourAt(const ColourPlanesOf<Plane>& p, float px, float py) {
  const float w = 1.0f / PlaneDepth(p.oow, px, py);
  return glm::vec3(PlaneDepth(p.colour_oow[0], px, py) * w, PlaneDepth(p.colour_oow[1], px, py) * w,
                   PlaneDepth(p.colour_oow[2], px, py) * w);
}

}  // namespace twinraster::cpu
