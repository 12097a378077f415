#include "book/book_lines.hpp"

#include <cmath>
#include <stdexcept>
#include <utility>

namespace twinraster::book {

namespace {

bool WithinReach(CanvasPoint p) {
  return std::abs(p.x) <= kFarthestEndpoint && std::abs(p.y) <= kFarthestEndpoint;  // false for NaN
}

// The index the demo reads its interpolated values at: (step - start) | 0. The step and the
// start differ by a whole number of steps less a rounding, so the index is in range.
std::size_t StepIndex(double step, double start) { return static_cast<std::size_t>(TruncateToInt32(step - start)); }

}  // namespace

std::vector<double> Interpolate(double i0, double d0, double i1, double d1) {
  if (i0 == i1) return {d0};
  std::vector<double> values;
  const double a = (d1 - d0) / (i1 - i0);
  double d = d0;
  for (double i = i0; i <= i1; i += 1) {
    values.push_back(d);
    d += a;
  }
  return values;
}

void DrawLine(DemoCanvas& canvas, CanvasPoint p0, CanvasPoint p1, Rgb8 colour) {
  if (!WithinReach(p0) || !WithinReach(p1)) {
    throw std::invalid_argument("DrawLine: an endpoint is not a number within 2^20 pixels of the canvas centre");
  }
  const double dx = p1.x - p0.x, dy = p1.y - p0.y;
  if (std::abs(dx) > std::abs(dy)) {
    if (dx < 0) std::swap(p0, p1);  // left to right
    const std::vector<double> ys = Interpolate(p0.x, p0.y, p1.x, p1.y);
    for (double x = p0.x; x <= p1.x; x += 1) canvas.PutPixel(x, ys.at(StepIndex(x, p0.x)), colour);
  } else {
    if (dy < 0) std::swap(p0, p1);  // bottom to top
    const std::vector<double> xs = Interpolate(p0.y, p0.x, p1.y, p1.x);
    for (double y = p0.y; y <= p1.y; y += 1) canvas.PutPixel(xs.at(StepIndex(y, p0.y)), y, colour);
  }
}

void DrawWireframeTriangle(DemoCanvas& canvas, CanvasPoint p0, CanvasPoint p1, CanvasPoint p2, Rgb8 colour) {
  DrawLine(canvas, p0, p1, colour);
  DrawLine(canvas, p1, p2, colour);
  DrawLine(canvas, p0, p2, colour);
}

}  // namespace twinraster::book
