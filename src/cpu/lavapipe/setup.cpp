#include "cpu/lavapipe/setup.hpp"

#include "cpu/platform.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace twinraster::cpu {

std::int32_t SnapToSubpixel(float window_coord) {
  // The instruction lavapipe's setup uses (cvtps2dq, one lane of it).
  return RoundHalfEvenToInt((window_coord - 0.5f) * static_cast<float>(kSubpixelOne));
}

std::int32_t SnapToSubpixelHalfAway(float window_coord) {
  const float scaled = (window_coord - 0.5f) * static_cast<float>(kSubpixelOne);
  const float rounded = scaled >= 0.0f ? scaled + 0.5f : scaled - 0.5f;
  // C's (int) as aarch64 converts (fcvtzs): toward zero, saturating, NaN to 0.
  if (rounded != rounded) return 0;
  if (rounded >= 2147483648.0f) return std::numeric_limits<std::int32_t>::max();
  if (rounded < -2147483648.0f) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(rounded);
}

bool SetUpTriangle(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2, const PixelRect& region,
                   TriangleSetup& out, const RasterRules& rules) {
  const auto snap = rules.triangles_round_half_away ? SnapToSubpixelHalfAway : SnapToSubpixel;
  std::int32_t x[3] = {snap(v0.x), snap(v1.x), snap(v2.x)};
  std::int32_t y[3] = {snap(v0.y), snap(v1.y), snap(v2.y)};

  const std::int64_t area = (std::int64_t{x[0]} - x[1]) * (std::int64_t{y[2]} - y[0]) -
                            (std::int64_t{x[2]} - x[0]) * (std::int64_t{y[0]} - y[1]);
  if (area == 0) return false;

  const WindowPos* w[3] = {&v0, &v1, &v2};
  out.swapped = area < 0;
  if (out.swapped) {
    std::swap(x[1], x[2]);
    std::swap(y[1], y[2]);
    std::swap(w[1], w[2]);
  }

  // Inclusive box of the pixels whose centres may be inside (llvmpipe's rounding; exact coverage
  // is the edge test's).
  const std::int64_t min_x = std::min({x[0], x[1], x[2]}), max_x = std::max({x[0], x[1], x[2]});
  const std::int64_t min_y = std::min({y[0], y[1], y[2]}), max_y = std::max({y[0], y[1], y[2]});
  PixelRect box;
  box.x0 = static_cast<int>(std::max<std::int64_t>(region.x0, min_x >> kSubpixelBits));
  box.x1 = static_cast<int>(std::min<std::int64_t>(region.x1, (max_x - 1) >> kSubpixelBits));
  box.y0 = static_cast<int>(std::max<std::int64_t>(region.y0, min_y >> kSubpixelBits));
  box.y1 = static_cast<int>(std::min<std::int64_t>(region.y1, (max_y - 1) >> kSubpixelBits));
  if (box.x0 > box.x1 || box.y0 > box.y1) return false;
  out.bounds = box;

  out.x = {x[0], x[1], x[2]};
  out.y = {y[0], y[1], y[2]};
  out.depth = MakeDepthPlane(*w[0], *w[1], *w[2]);
  return true;
}

bool Covers(const TriangleSetup& t, int px, int py) {
  if (px < t.bounds.x0 || px > t.bounds.x1 || py < t.bounds.y0 || py > t.bounds.y1) return false;
  for (const EdgeFunction& e : Edges(t)) {
    if (EdgeAt(e, px, py) <= 0) return false;
  }
  return true;
}

}  // namespace twinraster::cpu
