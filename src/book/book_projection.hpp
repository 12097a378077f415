// The chapter demo's ProjectVertex: a camera-space vertex to a canvas point, the fraction kept.
#pragma once

#include "book/book_chain.hpp"
#include "scene/scene.hpp"

namespace twinraster::book {

// A canvas point as the demo holds it: origin at the canvas centre, +x right, +y up, in pixels,
// not rounded (the demo's Pt).
struct CanvasPoint {
  double x = 0, y = 0;
  friend bool operator==(const CanvasPoint&, const CanvasPoint&) = default;
};

// ViewportToCanvas(v.x·d / v.z, v.y·d / v.z) with ViewportToCanvas(p) = (p.x·Cw / Vw, p.y·Ch / Vh),
// each expression evaluated left to right as the demo writes it. w is ignored, and nothing is
// clipped: a vertex behind the camera (z < 0) projects through the origin, one at z = 0 to
// infinity or NaN (the renderer refuses those before drawing).
CanvasPoint ProjectVertex(const Vertex4& v, const Viewport& viewport, const Canvas& canvas);

}  // namespace twinraster::book
