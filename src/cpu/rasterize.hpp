// Stage 5 applied row by row: which pixels of a row a triangle covers. Per row the three edge
// functions are linear in px with exact integer coefficients, so the covered pixels form one span
// that integer floor/ceil divisions give exactly, equal to testing every pixel of the box.
// Rows are shared between threads in interleaved bands; every thread walks all triangles in order
// over its own rows only, so each pixel sees the same triangles in the same order for any thread
// count.
#pragma once

#include "cpu/triangle_setup.hpp"

#include <algorithm>
#include <cstdint>

namespace twinraster::cpu {

struct Span {
  int begin = 0, end = 0;  // covered pixels [begin, end) of one row; empty when begin >= end
};

// Covered span of row py, with three divisions (one per edge).
Span CoveredSpan(const TriangleSetup& t, int py);

// The same spans for consecutive rows without dividing per row: for each edge the bound
// floor(-row_value / |step|) is kept as quotient and remainder and stepped exactly, like a DDA.
class SpanWalker {
 public:
  SpanWalker(const TriangleSetup& t, int py);  // positioned at row py
  Span span() const;                           // equals CoveredSpan(t, row)
  void NextRow();

 private:
  enum class Kind : std::uint8_t { kLowerBound, kUpperBound, kConstant };
  struct EdgeState {
    Kind kind = Kind::kConstant;
    std::int64_t q = 0, r = 0;    // floor(n / m) and n mod m, n = -(row value); or the row value
    std::int64_t m = 1;           // |step| along the row
    std::int64_t dq = 0, dr = 0;  // the same for the change of n from one row to the next
  };
  EdgeState edges_[3];
  int x_begin_, x_end_;
};

// Rows [band * kBandRows, (band + 1) * kBandRows) belong to part band % parts.
constexpr int kBandRows = 16;

struct RowShare {
  unsigned parts = 1;
  unsigned part = 0;
};

// Calls fn(row_begin, row_end) for each band of rows [0, height) that `share` owns.
template <class Fn>
void ForEachOwnedBand(const RowShare& share, int height, Fn&& fn) {
  const int parts = static_cast<int>(share.parts);
  for (int band = static_cast<int>(share.part); band * kBandRows < height; band += parts) {
    fn(band * kBandRows, std::min(height, (band + 1) * kBandRows));
  }
}

// Calls fn(py, span) for every non-empty covered span of the rows of `share` in t's box, top down.
template <class Fn>
void ForEachSpan(const TriangleSetup& t, const RowShare& share, Fn&& fn) {
  const int parts = static_cast<int>(share.parts);
  const int part = static_cast<int>(share.part);
  const int first_band = t.bounds.y0 / kBandRows;
  // The first band at or after first_band that this part owns.
  int band = first_band + ((part - first_band % parts) % parts + parts) % parts;
  for (; band * kBandRows <= t.bounds.y1; band += parts) {
    const int row_begin = std::max(t.bounds.y0, band * kBandRows);
    const int row_end = std::min(t.bounds.y1 + 1, (band + 1) * kBandRows);
    SpanWalker walker(t, row_begin);
    for (int py = row_begin; py < row_end; ++py, walker.NextRow()) {
      const Span span = walker.span();
      if (span.begin < span.end) fn(py, span);
    }
  }
}

}  // namespace twinraster::cpu
