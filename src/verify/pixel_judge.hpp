// The verifier's per-pixel stage for a band of rows: the frame's state that turns what the
// coverage shapes (coverage_shapes.hpp) offer into a PixelClass for each pixel. It does not know
// the shapes' geometry, nor walk a draw list (verifier.cpp does); its per-pixel buffers come from
// a pool (buffer_pool.hpp).
#pragma once

#include "image/image.hpp"
#include "verify/allowed_colours.hpp"
#include "verify/coverage_shapes.hpp"
#include "verify/verification.hpp"

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <vector>

namespace twinraster::verify {

// A band of the frame's rows [row0, row1): pass 1 records, per pixel, the farthest depth of the
// nearest surface certain to be written there; pass 2 offers every surface that may cover a
// pixel and is not surely behind it. Bands share nothing, so each may run on its own thread.
class FrameJudge {
 public:
  FrameJudge(const Image& image, Rgb8 background, bool reversed_z, int row0, int row1);
  ~FrameJudge();  // hands its per-pixel buffers back for the next frame
  FrameJudge(const FrameJudge&) = delete;
  FrameJudge& operator=(const FrameJudge&) = delete;

  PixelBox Clip(PixelBox box) const;  // to this band's rows
  // Pass 1: a surface certainly covers (x, y) and its depth is in `depth`.
  void Occlude(int x, int y, std::array<double, 2> depth);
  // Occlude at each pixel x0..x1 of row y, all in one tile, with depth_at(centre): the tile is
  // looked up once for the run, as a triangle's inside runs are most of what pass 1 writes.
  template <class DepthAt>
  void OccludeRun(int y, int x0, int x1, DepthAt&& depth_at);
  // Pass 2: whether a surface that may cover (x, y) with this depth may also be what shows there.
  bool MayShow(int x, int y, std::array<double, 2> depth) const;
  // `certain_line`: a line certain to cover (x, y) offers it (see Verification's shared edges).
  void Offer(int x, int y, const ColourRange& colours, bool certain_line = false);
  // MayShow, then Offer, at each pixel x0..x1 of row y, all in one tile: a triangle's inside run.
  template <class DepthAt, class ColourAt>
  void OfferRun(int y, int x0, int x1, DepthAt&& depth_at, ColourAt&& colour_at, bool certain_line);
  bool BackgroundMayShow(int x, int y) const { return Gap(x, y) == 0; }
  Rgb8 background() const { return background_; }

  // Whether a surface whose depth lies in `range` everywhere could matter anywhere in `box`: in
  // pass 1 lower the bound (`showing` false), in pass 2 show (`showing` true). Decided per 16 x 16
  // tile from the farthest bound in it, as of the last RefreshTiles, so hidden surfaces cost
  // nothing per pixel.
  bool CouldMatter(const PixelBox& box, std::array<double, 2> range, bool showing) const;
  void RefreshTiles();
  // Whether refreshing now pays: the pixels lowered since the last refresh outnumber what it reads.
  // Large triangles then cull the ones behind them in the same draw, not only in later ones.
  bool TilesWorthRefreshing() const { return lowered_ > std::size_t{kTile} * kTile / 2 * dirty_.size(); }
  static constexpr int kTile = 16;  // the side of the tiles CouldMatter decides by
  std::size_t TileOf(int x, int y) const { return std::size_t(((y - row0_) / kTile) * tiles_x_ + x / kTile); }
  std::size_t Tiles() const { return tile_gap_.size(); }
  PixelBox TileBox(std::size_t tile) const;  // its pixels, within the band and the image
  // Whether pass 1 found a surface certain to be written at every pixel of the tile.
  bool TileCertain(std::size_t tile) const { return tile_gap_[tile] > 0; }

  // The colours allowed, pixel by pixel, in a row run x0..x1 within one settled tile
  // (sole_surfaces.hpp), or false when the tile is not settled: its pixels got no offers, and the
  // colours given are the only ones its surfaces offer there.
  using SettledRun = std::function<bool(int y, int x0, int x1, ColourRange* colours)>;

  // The background where no surface is certain, then every pixel's class, written into `pixels`
  // (the whole frame's, row by row) and counted into `counts`, with the band's first and worst.
  // `settled` gives the settled tiles' runs (none when empty).
  void Finish(Verification& counts, std::vector<PixelClass>& pixels, const SettledRun& settled = {});
  // Each pixel's Reach, into `reach` (the whole frame's, row by row), after pass 2 and before
  // Finish (which offers the background): certain where pass 1 left a bound, maybe where any
  // surface offered.
  void WriteReach(std::vector<Reach>& reach) const;
  Rgb8 ImageColour(int x, int y) const {
    const std::uint8_t* p = image_->pixel(std::uint32_t(x), std::uint32_t(y));
    return {p[0], p[1], p[2]};
  }
  std::uint32_t width() const { return image_->width; }
  std::uint32_t height() const { return image_->height; }

 private:
  std::size_t Index(int x, int y) const { return std::size_t(y - row0_) * image_->width + std::size_t(x); }
  // The per-pixel buffers are cleared a tile at a time, when a surface first reaches it: a tile
  // no surface reaches (the background's) costs no clearing, and Finish classes it in one sweep.
  void Use(std::size_t tile) {
    if (!used_[tile]) UseFirst(tile);
  }
  void UseFirst(std::size_t tile);
  double Gap(int x, int y) const { return used_[TileOf(x, y)] ? gap_[Index(x, y)] : 0.0; }
  // Finish's classing of one pixel, counted into `v`.
  void Count(int x, int y, PixelClass c, int distance, int& worst_distance, Verification& v) const;
  void FinishUsed(int x, int y, Verification& v, int& worst_distance, std::vector<PixelClass>& pixels);
  void FinishUnused(int x0, int x1, int y, Verification& v, int& worst_distance, std::vector<PixelClass>& pixels) const;
  bool ShowsOnly(int x0, int x1, int y, Rgb8 colour) const;  // every pixel of the run, in r, g and b
  void FinishSettled(int x0, int x1, int y, const ColourRange* colours, Verification& v, int& worst_distance,
                     std::vector<PixelClass>& pixels) const;
  const Image* image_;
  Rgb8 background_;
  bool reversed_ = false;
  int row0_ = 0, row1_ = 0;
  double clear_key_ = 1;
  // Depth keys are the depth for LESS and its negation for GREATER, so nearer is smaller. Per
  // pixel, the key of the nearest certain surface's farthest depth, kept as clear key - key
  // (0: none), so that a fresh frame is all zeros.
  std::vector<double> gap_;
  // Offers pairwise overlap exactly when, channel by channel, the largest low end is no more than
  // the smallest high end (Helly's theorem in one dimension): kept that way, a pixel's class does
  // not depend on the order of the offers. All zeros when nothing was offered.
  struct State {
    Rgb8 max_lo{0, 0, 0};
    Rgb8 hi_gap{0, 0, 0};                   // 255 - the smallest high end
    std::uint8_t offers = 0;                // saturates at 2
    std::uint8_t closeness = 0;             // 255 - the image colour's distance from the nearest offer
    std::uint8_t background_closeness = 0;  // the same for the background's colour
    std::uint8_t not_certain_line = 0;      // 1: some offer came from other than a certain line
  };
  std::vector<State> state_;
  int tiles_x_ = 0;
  std::vector<double> tile_gap_;  // the smallest gap in each tile: its farthest bound
  std::vector<std::uint32_t> dirty_;
  std::size_t lowered_ = 0;  // pixels whose bound pass 1 lowered since RefreshTiles
  std::vector<char> is_dirty_;
  std::vector<char> used_;  // per tile: its pixels' gap_ and state_ are live (else all zeros)
};

// Occlude, MayShow and Offer run at nearly every pixel the verifier judges, hence inline.

// Depth keys: the depth itself for LESS, its negation for GREATER, so that nearer is smaller.
inline void FrameJudge::Occlude(int x, int y, std::array<double, 2> depth) {
  const double far_key = reversed_ ? -depth[0] : depth[1];
  // Written for sure only if it passes against the clear value whatever its depth.
  if (!(clear_key_ - far_key > Gap(x, y))) return;
  const std::size_t tile = TileOf(x, y);
  Use(tile);
  gap_[Index(x, y)] = clear_key_ - far_key;
  ++lowered_;
  if (!is_dirty_[tile]) is_dirty_[tile] = 1, dirty_.push_back(std::uint32_t(tile));
}

template <class DepthAt>
void FrameJudge::OccludeRun(int y, int x0, int x1, DepthAt&& depth_at) {
  const std::size_t tile = TileOf(x0, y), row = Index(0, y);
  bool wrote = false;
  for (int x = x0; x <= x1; ++x) {
    const std::array<double, 2> depth = depth_at(glm::dvec2(x + 0.5, y + 0.5));
    const double gap = clear_key_ - (reversed_ ? -depth[0] : depth[1]);
    if (!(gap > (used_[tile] ? gap_[row + std::size_t(x)] : 0.0))) continue;
    Use(tile);
    gap_[row + std::size_t(x)] = gap;
    wrote = true;
    ++lowered_;
  }
  if (wrote && !is_dirty_[tile]) is_dirty_[tile] = 1, dirty_.push_back(std::uint32_t(tile));
}

template <class DepthAt, class ColourAt>
void FrameJudge::OfferRun(int y, int x0, int x1, DepthAt&& depth_at, ColourAt&& colour_at, bool certain_line) {
  for (int x = x0; x <= x1; ++x) {
    const glm::dvec2 centre(x + 0.5, y + 0.5);
    if (MayShow(x, y, depth_at(centre))) Offer(x, y, colour_at(centre), certain_line);
  }
}

inline bool FrameJudge::MayShow(int x, int y, std::array<double, 2> depth) const {
  const double near_key = reversed_ ? -depth[1] : depth[0];
  const double near_gap = clear_key_ - near_key;
  return near_gap > 0 && near_gap >= Gap(x, y);
}

inline void FrameJudge::Offer(int x, int y, const ColourRange& colours, bool certain_line) {
  Use(TileOf(x, y));
  State& s = state_[Index(x, y)];
  const auto gap = [](std::uint8_t g, std::uint8_t hi) { return std::max<std::uint8_t>(g, std::uint8_t(255 - hi)); };
  s.max_lo = {std::max(s.max_lo.r, colours.lo.r), std::max(s.max_lo.g, colours.lo.g),
              std::max(s.max_lo.b, colours.lo.b)};
  s.hi_gap = {gap(s.hi_gap.r, colours.hi.r), gap(s.hi_gap.g, colours.hi.g), gap(s.hi_gap.b, colours.hi.b)};
  s.offers = std::uint8_t(std::min(2, s.offers + 1));
  s.closeness = std::max<std::uint8_t>(s.closeness, std::uint8_t(255 - colours.Distance(ImageColour(x, y))));
  s.background_closeness =
      std::max<std::uint8_t>(s.background_closeness, std::uint8_t(255 - colours.Distance(background_)));
  if (!certain_line) s.not_certain_line = 1;
}

}  // namespace twinraster::verify
