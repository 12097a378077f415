// ProjectVertex: the canvas point keeps its fraction, and each expression is evaluated left to
// right as the demo writes it.
#include "book/book_projection.hpp"

#include "support/catch.hpp"

using namespace twinraster;
using namespace twinraster::book;

namespace {
const Viewport kChapterViewport{1, 1, 1};  // the demos' viewport_size = 1, projection_plane_z = 1
const Canvas kChapterCanvas{600, 600};
}  // namespace

TEST_CASE("ProjectVertex on the demos' numbers, by hand", "[book][projection]") {
  // Figure 10-2's vertex 0: camera space (-0.5, 1, 8): (-0.5/8·600, 1/8·600) = (-37.5, 75), exact.
  REQUIRE(ProjectVertex({-0.5, 1, 8, 1}, kChapterViewport, kChapterCanvas) == CanvasPoint{-37.5, 75});
  // Vertex 4 at (-0.5, 1, 6): -0.5/6 = -0.08333333333333333 (rounded), ·600 = -49.999999999999997
  // before rounding, which rounds to -50; 1/6·600 likewise to 100.
  REQUIRE(ProjectVertex({-0.5, 1, 6, 1}, kChapterViewport, kChapterCanvas) == CanvasPoint{-50, 100});
  // Figure 10-3's second cube, vertex 0 at (2.25, 3, 8.5): 158.82..., 211.76...: the fraction stays.
  const CanvasPoint p = ProjectVertex({2.25, 3, 8.5, 1}, kChapterViewport, kChapterCanvas);
  REQUIRE(p.x == Approx(158.8235294117647).epsilon(1e-15));
  REQUIRE(p.y == Approx(211.76470588235293).epsilon(1e-15));
  // No clipping: behind the camera (z = -2) the point goes through the origin to the other side.
  REQUIRE(ProjectVertex({1, 1, -2, 1}, kChapterViewport, kChapterCanvas) == CanvasPoint{-300, -300});
  // w is not used.
  REQUIRE(ProjectVertex({-0.5, 1, 8, 5}, kChapterViewport, kChapterCanvas) == CanvasPoint{-37.5, 75});
}

TEST_CASE("ProjectVertex uses the scene's d, viewport and canvas, in the demo's order of operations",
          "[book][projection]") {
  // Viewport 2 x 1 at d = 2, canvas 800 x 300, vertex (1, 0.5, 4): viewport point (1·2/4, 0.5·2/4)
  // = (0.5, 0.25), canvas point (0.5·800/2, 0.25·300/1) = (200, 75).
  REQUIRE(ProjectVertex({1, 0.5, 4, 1}, Viewport{2, 1, 2}, Canvas{800, 300}) == CanvasPoint{200, 75});
  // (x·d)/z, not x·(d/z): (0.1·3)/0.3 = 0.30000000000000004/0.3 = 1.0000000000000002, where
  // 0.1·(3/0.3) = 0.1·10 = 1; then ·600 gives 600.0000000000001, not 600.
  const CanvasPoint p = ProjectVertex({0.1, 0, 0.3, 1}, Viewport{1, 1, 3}, kChapterCanvas);
  REQUIRE(p.x == 600.0000000000001);
  REQUIRE(p.x != 600.0);
}
