#include "cpu/swiftshader/coverage.hpp"

#include "cpu/floor_division.hpp"

#include <algorithm>
#include <bit>

namespace twinraster::cpu {

namespace {

// ceil(y / 16): the first row whose centre is at or below y.
std::int64_t FirstRow(std::int32_t y) { return CeilDiv(y, kOutlineOne); }

}  // namespace

bool OutlineBounds(const SnappedPoint* points, int count, int width, int height, PixelRect& bounds) {
  std::int32_t min_x = points[0].x, max_x = points[0].x, min_y = points[0].y, max_y = points[0].y;
  for (int i = 1; i < count; ++i) {
    min_x = std::min(min_x, points[i].x), max_x = std::max(max_x, points[i].x);
    min_y = std::min(min_y, points[i].y), max_y = std::max(max_y, points[i].y);
  }
  // Rows with min_y <= 16 py < max_y; columns with ceil(min_x / 16) <= px < ceil(max_x / 16).
  bounds.y0 = static_cast<int>(std::max<std::int64_t>(0, FirstRow(min_y)));
  bounds.y1 = static_cast<int>(std::min<std::int64_t>(height, FirstRow(max_y))) - 1;
  bounds.x0 = static_cast<int>(std::max<std::int64_t>(0, FirstRow(min_x)));
  bounds.x1 = static_cast<int>(std::min<std::int64_t>(width, FirstRow(max_x))) - 1;
  return bounds.y0 <= bounds.y1 && bounds.x0 <= bounds.x1;
}

Span OutlineSpan(const SnappedPoint* points, int count, bool d, int width, int py) {
  const std::int64_t row = std::int64_t{py} * kOutlineOne;
  std::int64_t left = 0, right = 0;
  bool has_left = false, has_right = false;
  for (int i = 0; i < count; ++i) {
    const int next = i + 1 == count ? 0 : i + 1;
    const SnappedPoint& a = points[d ? i : next];
    const SnappedPoint& b = points[d ? next : i];
    if (a.y == b.y) continue;
    const bool upwards = b.y < a.y;  // writes the right end
    const SnappedPoint& top = upwards ? b : a;
    const SnappedPoint& bottom = upwards ? a : b;
    if (row < top.y || row >= bottom.y) continue;
    // x on the edge at this row is top.x + dx (row - top.y) / dy, in 1/16 pixel; its ceiling in pixels.
    const std::int64_t dx = std::int64_t{bottom.x} - top.x, dy = std::int64_t{bottom.y} - top.y;
    const std::int64_t x = CeilDiv(std::int64_t{top.x} * dy + dx * (row - top.y), dy * kOutlineOne);
    const std::int64_t clamped = std::clamp<std::int64_t>(x, 0, width);
    if (upwards) {
      right = clamped, has_right = true;
    } else {
      left = clamped, has_left = true;
    }
  }
  // A closed polygon crosses each of its rows as often upwards as downwards, so both ends are set;
  // the flags only guard a row outside it.
  if (!has_left || !has_right || left >= right) return {};
  return {static_cast<int>(left), static_cast<int>(right)};
}

bool OutlineWinding(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& c) {
  const float x0 = static_cast<float>(a.x), x1 = static_cast<float>(b.x), x2 = static_cast<float>(c.x);
  const float y0 = static_cast<float>(a.y), y1 = static_cast<float>(b.y), y2 = static_cast<float>(c.y);
  float area = (y0 - y2) * x1 + (y2 - y1) * x0 + (y1 - y0) * x2;
  const std::uint32_t signs = std::bit_cast<std::uint32_t>(a.clip.w) ^ std::bit_cast<std::uint32_t>(b.clip.w) ^
                              std::bit_cast<std::uint32_t>(c.clip.w);
  if ((signs >> 31) != 0) area = -area;
  return area > 0.0f;
}

}  // namespace twinraster::cpu
