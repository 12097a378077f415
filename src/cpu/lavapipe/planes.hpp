// Stage 6 for a Gouraud colour as lavapipe interpolates it: perspective-correct. Each channel c is
// set up, like depth, as a plane through c·(1/w) at the three vertices, and 1/w gets a plane of its
// own; at a pixel the colour is plane_c · (1 / plane_1/w) (ColourAt, cpu/packets.hpp). This file
// builds lavapipe's planes, evaluated with two fused multiply-adds at the pixel's integer indices;
// SwiftShader's are built from its snapped vertices (cpu/swiftshader/planes.hpp). It does not
// evaluate them per pixel (ColourAt and fragment_ops.hpp do).
#pragma once

#include "cpu/lavapipe/clipping.hpp"
#include "cpu/lavapipe/plane.hpp"
#include "cpu/packets.hpp"

namespace twinraster::cpu {

using ColourPlanes = ColourPlanesOf<DepthPlane>;

// v0, v1, v2 in the order triangle setup left them (after the winding swap), as the depth plane.
// `fused`: evaluated with fmaf (RasterRules::fused_multiply_add), as the depth plane.
ColourPlanes MakeColourPlanes(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, bool fused = true);

}  // namespace twinraster::cpu
