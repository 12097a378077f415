// How the verifier walks a shape's pixels: row by row, in runs that stay within one of the
// judge's tiles, asking first whether a run can matter (TileCull) and visiting a triangle's inside
// pixels without testing its edges. It decides nothing about a pixel; the visitors do.
#pragma once

#include "verify/coverage_shapes.hpp"
#include "verify/pixel_judge.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <type_traits>

namespace twinraster::verify {

// visit(x, y, centre, coverage) for each pixel of `box` the shape may cover. A triangle's rows
// are inside in their middle: those pixels are visited without testing the edges, a run of them
// within one tile at a time, by inside(y, x0, x1). `keep(y, x0, x1)` is asked first for each row's
// run of pixels within one tile, which is skipped when it says no.
template <class Shape, class Keep, class Visit, class Inside>
void ScanRuns(const Shape& shape, const PixelBox& box, Keep&& keep, Visit&& visit, Inside&& inside) {
  constexpr int kTile = FrameJudge::kTile;
  for (int y = box.y0; y <= box.y1; ++y) {
    int in0 = box.x1 + 1, in1 = box.x1, x0 = box.x0, x1 = box.x1;
    if constexpr (std::is_same_v<Shape, TriangleShape>) {
      const TriangleShape::RowSpans spans = shape.Spans(y);
      x0 = std::max(x0, spans.reach[0]), x1 = std::min(x1, spans.reach[1]);
      const std::array<int, 2> span = spans.inside;
      if (span[0] <= span[1]) in0 = std::max(span[0], box.x0), in1 = std::min(span[1], box.x1);
    }
    const auto tested = [&](int from, int to) {
      for (int x = from; x <= to; ++x) {
        const glm::dvec2 centre(x + 0.5, y + 0.5);
        const Coverage c = shape.Covers(centre);
        if (c != Coverage::kOut) visit(x, y, centre, c);
      }
    };
    for (int run0 = x0; run0 <= x1; run0 = (run0 / kTile + 1) * kTile) {
      const int run1 = std::min(x1, (run0 / kTile + 1) * kTile - 1);
      if (!keep(y, run0, run1)) continue;
      const int a = std::max(run0, in0), b = std::min(run1, in1);  // the run's inside part
      if (a > b) {
        tested(run0, run1);
        continue;
      }
      tested(run0, a - 1);
      inside(y, a, b);
      tested(b + 1, run1);
    }
  }
}

// ScanRuns visiting the inside pixels one by one too.
template <class Shape, class Keep, class Visit>
void Scan(const Shape& shape, const PixelBox& box, Keep&& keep, Visit&& visit) {
  ScanRuns(shape, box, keep, visit, [&](int y, int x0, int x1) {
    for (int x = x0; x <= x1; ++x) visit(x, y, glm::dvec2(x + 0.5, y + 0.5), Coverage::kIn);
  });
}

// Scan's `keep` for a surface whose depth lies in `range` everywhere: skips the runs of tiles where
// it can matter at no pixel (FrameJudge::CouldMatter on the tile), unless the options turn that off.
// A triangle wider or taller than a tile is asked again with its depth along the run alone, so that
// a face behind another in most tiles is skipped there, not wherever its whole range overlaps.
template <class Shape>
struct TileCull {
  const FrameJudge& judge;
  const Shape& shape;
  const PixelBox& box;
  std::array<double, 2> range;
  bool showing, on;
  bool operator()(int y, int x0, int x1) const {
    if (!on) return true;
    if (!judge.CouldMatter({x0, y, x1, y}, range, showing)) return false;
    if constexpr (std::is_same_v<Shape, TriangleShape>) {
      if (box.x1 - box.x0 >= FrameJudge::kTile || box.y1 - box.y0 >= FrameJudge::kTile)
        return judge.CouldMatter({x0, y, x1, y}, shape.DepthAlong(y, x0, x1), showing);
    }
    return true;
  }
};

}  // namespace twinraster::verify
