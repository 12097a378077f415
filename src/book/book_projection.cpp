#include "book/book_projection.hpp"

namespace twinraster::book {

CanvasPoint ProjectVertex(const Vertex4& v, const Viewport& viewport, const Canvas& canvas) {
  const double d = viewport.distance;
  const double vx = v[0] * d / v[2], vy = v[1] * d / v[2];  // the viewport point
  return {vx * canvas.width / viewport.width, vy * canvas.height / viewport.height};
}

}  // namespace twinraster::book
