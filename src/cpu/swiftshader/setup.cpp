#include "cpu/swiftshader/setup.hpp"

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
