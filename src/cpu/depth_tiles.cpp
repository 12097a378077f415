#include "cpu/depth_tiles.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster::cpu {

namespace {

// The largest (kLess) or smallest (kGreater) depth stored in a rectangle.
template <bool kLargest>
float Farthest(const Framebuffer& fb, int x_begin, int x_end, int row_begin, int row_end) {
  float farthest = fb.depth_row(row_begin)[x_begin];
  for (int py = row_begin; py < row_end; ++py) {
    const float* row = fb.depth_row(py);
    for (int px = x_begin; px < x_end; ++px) {
      farthest = kLargest ? (row[px] > farthest ? row[px] : farthest) : (row[px] < farthest ? row[px] : farthest);
    }
  }
  return farthest;
}

// The bound from the plane's extremes over the box (in double), widened by `slack` and clamped as
// fragments are. A plane whose terms reach float's range could round a term to inf and a fragment
// to NaN, which either clamp makes 0 or 1: then no bound short of the extreme holds.
double Bounded(double lowest, double highest, double scale, double slack, DepthCompare op) {
  const bool representable = scale < 0x1p100;  // also false for NaN
  if (op == DepthCompare::kLess) {
    const double z = lowest - slack;
    return representable && z > 0 ? std::min(z, 1.0) : 0.0;
  }
  const double z = highest + slack;
  return representable && z < 1 ? std::max(z, 0.0) : 1.0;
}

}  // namespace

double NearestDepth(const DepthPlane& plane, const PixelRect& box, DepthCompare op) {
  const double a0 = plane.a0, dzdx = plane.dzdx, dzdy = plane.dzdy;
  const double x0 = box.x0, x1 = box.x1, y0 = box.y0, y1 = box.y1;
  // The plane is affine, so over the box it is extreme at corners. Each product of a float and a
  // pixel index is exact in double.
  const double lowest = a0 + std::min(dzdx * x0, dzdx * x1) + std::min(dzdy * y0, dzdy * y1);
  const double highest = a0 + std::max(dzdx * x0, dzdx * x1) + std::max(dzdy * y0, dzdy * y1);
  // Each rounding (two with fma, four without) is at most 2^-24 of a value no larger than `scale`
  // (and 2^-150 when subnormal); 2^-21 covers four twice over, and the double sums above too.
  const double scale = std::fabs(a0) + std::fabs(dzdx) * std::max(std::fabs(x0), std::fabs(x1)) +
                       std::fabs(dzdy) * std::max(std::fabs(y0), std::fabs(y1));
  return Bounded(lowest, highest, scale, scale * 0x1p-21 + 0x1p-126, op);
}

double NearestDepth(const AnchoredPlane& plane, const PixelRect& box, DepthCompare op) {
  const double a = plane.a, b = plane.b, c = plane.c;
  // xf = px - x0 and yf = py - y0 in double are exact; in float each may round once (an anchor
  // 2^24 pixels or more away), so six roundings in all, each at most 2^-24 of `scale`.
  const double x0 = box.x0 - double{plane.x0}, x1 = box.x1 - double{plane.x0};
  const double y0 = box.y0 - double{plane.y0}, y1 = box.y1 - double{plane.y0};
  const double lowest = c + std::min(a * x0, a * x1) + std::min(b * y0, b * y1);
  const double highest = c + std::max(a * x0, a * x1) + std::max(b * y0, b * y1);
  const double scale = std::fabs(c) + std::fabs(a) * std::max(std::fabs(x0), std::fabs(x1)) +
                       std::fabs(b) * std::max(std::fabs(y0), std::fabs(y1));
  // 2^-21 covers six roundings; a denormal flushed to 0 (SwiftShader's threads) moves a value by
  // less than 2^-126, four times at most.
  return Bounded(lowest, highest, scale, scale * 0x1p-21 + 0x1p-122, op);
}

DepthTiles::DepthTiles(std::uint32_t width, std::uint32_t height, DepthCompare op)
    : columns_((width + kTileSize - 1) / kTileSize),
      stride_((columns_ + 63) / 64 * 64),
      op_(op),
      farthest_(stride_ * ((height + kTileSize - 1) / kTileSize), ClearDepth(op)),
      dirty_(farthest_.size(), 0) {}

template <class Plane>
bool DepthTiles::Hidden(const PixelRect& bounds, const Plane& depth, int band, int row_begin, int row_end) const {
  const float* tiles = farthest_.data() + static_cast<std::size_t>(band) * stride_;
  const int first = bounds.x0 / kTileSize, last = bounds.x1 / kTileSize;
  float farthest = tiles[first];
  for (int tx = first + 1; tx <= last; ++tx) {
    farthest = op_ == DepthCompare::kLess ? std::max(farthest, tiles[tx]) : std::min(farthest, tiles[tx]);
  }
  // Nothing to gain where the tiles still hold the clear depth (only a fragment exactly at it
  // would be rejected), so skip the bound's arithmetic there.
  if (farthest == ClearDepth(op_)) return false;
  const PixelRect box{bounds.x0, row_begin, bounds.x1, row_end - 1};
  const double nearest = NearestDepth(depth, box, op_);
  // Every fragment is at least as far as `nearest`, which is at least as far as every stored depth
  // in these tiles: the strict test fails everywhere.
  return op_ == DepthCompare::kLess ? nearest >= farthest : nearest <= farthest;
}

template bool DepthTiles::Hidden(const PixelRect&, const DepthPlane&, int, int, int) const;
template bool DepthTiles::Hidden(const PixelRect&, const AnchoredPlane&, int, int, int) const;

void DepthTiles::Refresh(const Framebuffer& fb, int band) {
  const int width = static_cast<int>(fb.width()), height = static_cast<int>(fb.height());
  const int row_begin = band * kTileSize, row_end = std::min(height, row_begin + kTileSize);
  const std::size_t offset = static_cast<std::size_t>(band) * stride_;
  for (std::size_t tx = 0; tx < columns_; ++tx) {
    if (dirty_[offset + tx] == 0) continue;
    dirty_[offset + tx] = 0;
    const int x_begin = static_cast<int>(tx) * kTileSize, x_end = std::min(width, x_begin + kTileSize);
    farthest_[offset + tx] = op_ == DepthCompare::kLess ? Farthest<true>(fb, x_begin, x_end, row_begin, row_end)
                                                        : Farthest<false>(fb, x_begin, x_end, row_begin, row_end);
  }
}

}  // namespace twinraster::cpu
