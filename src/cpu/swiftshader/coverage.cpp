#include "cpu/swiftshader/coverage.hpp"

#include "cpu/floor_division.hpp"

#include <algorithm>

namespace twinraster::cpu {

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

}  // namespace twinraster::cpu
