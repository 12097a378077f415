// Stage 6 as SwiftShader interpolates (docs/swiftshader-rules.md, "Depth" and "Colour"): a plane
// anchored at a snapped vertex (x0, y0), evaluated at pixel (px, py) as
//   (xf * a) + (c + (yf * b)),  xf = px - x0, yf = py - y0,
// every operation rounded to float, the y term added first. Depth is then clamped with max before
// min. It does not build the planes (planes.hpp); lavapipe's planes, anchored at pixel
// (0, 0) and evaluated x term first, are cpu/lavapipe/plane.hpp's.
#pragma once

#include "cpu/packets.hpp"

namespace twinraster::cpu {

struct AnchoredPlane {
  float a = 0;  // per pixel to the right
  float b = 0;  // per pixel down
  float c = 0;  // the value at the anchor
  float x0 = 0, y0 = 0;
};

// The plane's value at pixel (px, py), unclamped.
inline float PlaneDepth(const AnchoredPlane& p, float px, float py) {
  const float xf = px - p.x0, yf = py - p.y0;
  return xf * p.a + (p.c + yf * p.b);
}

// The clamp to [0, 1] as SwiftShader's Min(Max(z, 0), 1): a NaN becomes 0 (lavapipe's order makes
// it 1), and -0.0 becomes +0.0.
inline float ClampDepthMaxFirst(float z) {
  z = z > 0.0f ? z : 0.0f;
  return z < 1.0f ? z : 1.0f;
}

// The colour planes of a Gouraud primitive, in SwiftShader's anchored form.
using AnchoredColourPlanes = ColourPlanesOf<AnchoredPlane>;

// What the depth test sees at pixel (px, py).
inline float DepthAt(const AnchoredPlane& p, int px, int py) {
  return ClampDepthMaxFirst(PlaneDepth(p, static_cast<float>(px), static_cast<float>(py)));
}

}  // namespace twinraster::cpu
