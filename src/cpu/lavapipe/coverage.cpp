#include "cpu/lavapipe/coverage.hpp"

#include "cpu/floor_division.hpp"

#include <cstdint>

namespace twinraster::cpu {

Span CoveredSpan(const TriangleSetup& t, int py) {
  const std::array<EdgeFunction, 3> edges = Edges(t);
  return CoveredSpan(edges.data(), edges.size(), t.bounds, py);
}

Span CoveredSpan(const EdgeFunction* edges, std::size_t count, const PixelRect& bounds, int py) {
  std::int64_t begin = bounds.x0;
  std::int64_t end = std::int64_t{bounds.x1} + 1;
  for (std::size_t i = 0; i < count; ++i) {
    const EdgeFunction& e = edges[i];
    // Along the row the edge function is row_value + step * px; covered needs > 0.
    const std::int64_t row_value = e.c + e.dcdy * (std::int64_t{py} * kSubpixelOne);
    const std::int64_t step = -e.dcdx * kSubpixelOne;
    if (step > 0) {
      begin = std::max(begin, FloorDiv(-row_value, step) + 1);  // px > -row_value / step
    } else if (step < 0) {
      end = std::min(end, CeilDiv(row_value, -step));  // px < row_value / -step
    } else if (row_value <= 0) {
      return {};
    }
    if (begin >= end) return {};
  }
  return {static_cast<int>(begin), static_cast<int>(end)};
}

SpanWalker::SpanWalker(const TriangleSetup& t, int py) : x_begin_(t.bounds.x0), x_end_(t.bounds.x1 + 1) {
  const std::array<EdgeFunction, 3> edges = Edges(t);
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeFunction& e = edges[i];
    EdgeState& s = edges_[i];
    const std::int64_t row_value = e.c + e.dcdy * (std::int64_t{py} * kSubpixelOne);
    const std::int64_t row_change = e.dcdy * kSubpixelOne;  // of row_value per row down
    const std::int64_t step = -e.dcdx * kSubpixelOne;
    if (step == 0) {
      s.kind = Kind::kConstant;  // q is the row value itself, dq its change
      s.q = row_value;
      s.dq = row_change;
      continue;
    }
    s.kind = step > 0 ? Kind::kLowerBound : Kind::kUpperBound;
    s.m = step > 0 ? step : -step;
    s.q = FloorDiv(-row_value, s.m);
    s.r = -row_value - s.q * s.m;
    s.dq = FloorDiv(-row_change, s.m);
    s.dr = -row_change - s.dq * s.m;
  }
}

}  // namespace twinraster::cpu
