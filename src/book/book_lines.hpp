// The chapter demo's line drawing: Interpolate, DrawLine and DrawWireframeTriangle, step for
// step in double, on a DemoCanvas.
#pragma once

#include "book/book_canvas.hpp"
#include "book/book_projection.hpp"
#include "scene/scene.hpp"

#include <vector>

namespace twinraster::book {

// The demo walks every step of a line, on the canvas or off it, and keeps every interpolated
// value in an array. A point this far from the canvas centre (a vertex close to the camera plane
// z = 0) means millions of steps, and at z = 0 the walk never ends; so DrawLine refuses endpoints
// beyond ±2^20 pixels, and within that bound `| 0` never wraps.
inline constexpr double kFarthestEndpoint = 1048576.0;

// The dependent value d at each independent value i from i0 up to i1: [d0] when i0 == i1;
// otherwise a = (d1 - d0) / (i1 - i0), and for i = i0, i0 + 1, ... while i <= i1, the current d,
// then d += a. Both i and d accumulate (rounded at every step), and i keeps i0's fraction, so
// there are floor(i1 - i0) + 1 values, give or take the rounding of i. i1 < i0 gives none.
std::vector<double> Interpolate(double i0, double d0, double i1, double d1);

// Steps along x when |dx| > |dy| (strictly), else along y, from the end with the smaller
// coordinate; each step puts the pixel (x, ys[(x - x0) | 0]), or (xs[(y - y0) | 0], y). The far
// end's pixel is drawn only if a whole number of steps reaches it. Throws std::invalid_argument
// for an endpoint that is not finite or is beyond kFarthestEndpoint.
void DrawLine(DemoCanvas& canvas, CanvasPoint p0, CanvasPoint p1, Rgb8 colour);

// DrawLine(p0, p1), DrawLine(p1, p2), DrawLine(p0, p2), in that order.
void DrawWireframeTriangle(DemoCanvas& canvas, CanvasPoint p0, CanvasPoint p1, CanvasPoint p2, Rgb8 colour);

}  // namespace twinraster::book
