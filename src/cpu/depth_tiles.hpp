// Stage 7's early rejection (a "hierarchical Z"): for each 16x16 tile of the depth buffer, a bound
// on the farthest depth stored in it, so that a primitive none of whose fragments could be nearer
// than that bound is skipped in the tile. Both depth tests are strict, so such a primitive would
// change no pixel there: skipping it is exact, and the image stays the device's. A million cubes
// drawn front to back hide most of their triangles this way. It does not rasterize anything.
// The bounds are refreshed from the depth buffer after each chunk, for the tiles drawn into; in
// between they are stale, which stays safe because stored depths only ever move nearer.
#pragma once

#include "cpu/fragment_ops.hpp"
#include "cpu/lavapipe/plane.hpp"
#include "cpu/packets.hpp"
#include "cpu/swiftshader/plane.hpp"

#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// A tile row is one band (kBandRows), so the part that owns a band owns its tiles.
constexpr int kTileSize = kBandRows;

// A bound on the depth the fragments of a plane can have inside `box` (pixel indices, inclusive),
// as DepthAt computes them in float: no fragment is nearer than this (for kLess, no smaller; for
// kGreater, no larger). Evaluated in double at the box's corners, widened by the float rounding of
// DepthAt's operations (two fused multiply-adds, or four separate ones), then clamped to [0, 1] as
// the fragments are.
double NearestDepth(const DepthPlane& plane, const PixelRect& box, DepthCompare op);
// The same for SwiftShader's plane: its roundings, from its anchor, clamped max before min.
double NearestDepth(const AnchoredPlane& plane, const PixelRect& box, DepthCompare op);

class DepthTiles {
 public:
  DepthTiles(std::uint32_t width, std::uint32_t height, DepthCompare op);  // every tile clear

  // True when a primitive (a triangle or a line) with this box and depth plane certainly passes
  // the depth test nowhere in rows [row_begin, row_end) of band.
  template <class Plane>
  bool Hidden(const PixelRect& bounds, const Plane& depth, int band, int row_begin, int row_end) const;

  // The tiles a span of row py covers may now hold nearer depths.
  void MarkDrawn(int py, Span span) {
    std::uint8_t* row = dirty_.data() + static_cast<std::size_t>(py / kTileSize) * stride_;
    for (int tx = span.begin / kTileSize; tx <= (span.end - 1) / kTileSize; ++tx) row[tx] = 1;
  }

  // Recomputes the bounds of band's tiles drawn into since the last refresh.
  void Refresh(const Framebuffer& fb, int band);

 private:
  std::size_t columns_;
  std::size_t stride_;  // columns_ rounded up to 64, so that bands of different parts share no cache line
  DepthCompare op_;
  std::vector<float> farthest_;      // per tile, band after band: no stored depth in it is farther than this
  std::vector<std::uint8_t> dirty_;  // per tile: drawn into since the last Refresh
};

}  // namespace twinraster::cpu
