// Stage 5 applied row by row: which pixels of a row a triangle covers. Per row the three edge
// functions are linear in px with exact integer coefficients, so the covered pixels form one span
// that integer floor/ceil divisions give exactly, equal to testing every pixel of the box.
// Rows are shared between threads in interleaved bands of kBandRows rows; every thread draws all
// triangles in order over its own bands only, so each pixel sees the same triangles in the same
// order for any thread count.
#pragma once

#include "cpu/lavapipe/setup.hpp"
#include "cpu/packets.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// Covered span of row py, with three divisions (one per edge).
Span CoveredSpan(const TriangleSetup& t, int py);
// The same for any convex polygon given by its edge functions (a line's four), inside `bounds`.
Span CoveredSpan(const EdgeFunction* edges, std::size_t count, const PixelRect& bounds, int py);

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

inline Span SpanWalker::span() const {
  std::int64_t begin = x_begin_, end = x_end_;
  for (const EdgeState& s : edges_) {
    switch (s.kind) {
      case Kind::kLowerBound:  // px > n / m, that is px >= floor(n / m) + 1
        begin = std::max(begin, s.q + 1);
        break;
      case Kind::kUpperBound:  // px < -n / m, that is px < -floor(n / m)
        end = std::min(end, -s.q);
        break;
      case Kind::kConstant:
        if (s.q <= 0) return {};
        break;
    }
  }
  if (begin >= end) return {};
  return {static_cast<int>(begin), static_cast<int>(end)};
}

inline void SpanWalker::NextRow() {
  for (EdgeState& s : edges_) {
    s.q += s.dq;
    if (s.kind == Kind::kConstant) continue;
    s.r += s.dr;
    if (s.r >= s.m) {
      s.r -= s.m;
      s.q += 1;
    }
  }
}

// Boxes narrower than this many pixels are scanned pixel by pixel: a few additions per pixel cost
// less than the six 64-bit divisions that start a SpanWalker (a million distant cubes are
// millions of triangles a few pixels wide).
constexpr int kNarrowTriangle = 8;

// The covered spans of rows [row_begin, row_end) of a narrow triangle, by testing each pixel of
// its box. A triangle's covered pixels in a row are contiguous, so they form one span, the same
// one SpanWalker computes.
template <class SpanFn>
void ScanNarrowTriangle(const TriangleSetup& t, int row_begin, int row_end, SpanFn&& on_span) {
  const std::array<EdgeFunction, 3> edges = Edges(t);
  const std::int64_t s0 = edges[0].dcdx * kSubpixelOne, s1 = edges[1].dcdx * kSubpixelOne,
                     s2 = edges[2].dcdx * kSubpixelOne;
  for (int py = row_begin; py < row_end; ++py) {
    std::int64_t e0 = EdgeAt(edges[0], t.bounds.x0, py), e1 = EdgeAt(edges[1], t.bounds.x0, py),
                 e2 = EdgeAt(edges[2], t.bounds.x0, py);
    int begin = -1, end = -1;
    for (int px = t.bounds.x0; px <= t.bounds.x1; ++px, e0 -= s0, e1 -= s1, e2 -= s2) {
      if (e0 > 0 && e1 > 0 && e2 > 0) {
        if (begin < 0) begin = px;
        end = px + 1;
      } else if (begin >= 0) {
        break;
      }
    }
    if (begin >= 0) on_span(t, py, Span{begin, end});
  }
}

// The covered spans of rows [row_begin, row_end) of t, which must lie inside its bounds: on_span(t,
// py, span) for each non-empty one, top down.
template <class SpanFn>
void RasterizeRows(const TriangleSetup& t, int row_begin, int row_end, SpanFn&& on_span) {
  if (t.bounds.x1 - t.bounds.x0 < kNarrowTriangle) {
    ScanNarrowTriangle(t, row_begin, row_end, on_span);
    return;
  }
  SpanWalker walker(t, row_begin);
  for (int py = row_begin; py < row_end; ++py, walker.NextRow()) {
    const Span span = walker.span();
    if (span.begin < span.end) on_span(t, py, span);
  }
}

// Rasterizes the bands `share` owns one after the other, so that a band's depth and colour rows
// stay in cache: for each owned band, top down, on_band(row_begin, row_end) first, then
// on_span(triangle, py, span) for each covered span in the band of every triangle overlapping it,
// triangles in list order. Each pixel sees the same triangles in the same order as drawing one
// whole triangle after the other would give. (The renderer does the same from the bins that
// cpu/chunk_assembly.hpp fills during setup; this simple form serves clearing and coverage counting.)
template <class BandFn, class SpanFn>
void RasterizeBands(const std::vector<std::vector<TriangleSetup>>& triangles, const RowShare& share, int height,
                    BandFn&& on_band, SpanFn&& on_span) {
  const int band_count = (height + kBandRows - 1) / kBandRows;
  for (int band = static_cast<int>(share.part); band < band_count; band += static_cast<int>(share.parts)) {
    const int band_begin = band * kBandRows, band_end = std::min(height, band_begin + kBandRows);
    on_band(band_begin, band_end);
    for (const std::vector<TriangleSetup>& chunk : triangles) {
      for (const TriangleSetup& t : chunk) {
        if (band < FirstBand(t.bounds) || band > LastBand(t.bounds)) continue;
        RasterizeRows(t, std::max(t.bounds.y0, band_begin), std::min(t.bounds.y1 + 1, band_end), on_span);
      }
    }
  }
}

}  // namespace twinraster::cpu
