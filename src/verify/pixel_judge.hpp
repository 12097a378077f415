// The verifier's per-pixel stage for a band of rows: the frame's state that turns what the
// coverage shapes (coverage_shapes.hpp) offer into a PixelClass for each pixel. It does not know
// the shapes' geometry, nor walk a draw list (verifier.cpp does); its per-pixel buffers come from
// a pool (buffer_pool.hpp).
#pragma once

#include "image/image.hpp"
#include "verify/allowed_colours.hpp"
#include "verify/coverage_shapes.hpp"
#include "verify/verification.hpp"

#include <array>
#include <cstdint>
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
  // Pass 2: whether a surface that may cover (x, y) with this depth may also be what shows there.
  bool MayShow(int x, int y, std::array<double, 2> depth) const;
  // `certain_line`: a line certain to cover (x, y) offers it (see Verification's shared edges).
  void Offer(int x, int y, const ColourRange& colours, bool certain_line = false);
  bool BackgroundMayShow(int x, int y) const { return Gap(x, y) == 0; }
  Rgb8 background() const { return background_; }

  // Whether a surface whose depth lies in `range` everywhere could matter anywhere in `box`: in
  // pass 1 lower the bound (`showing` false), in pass 2 show (`showing` true). Decided per 16 x 16
  // tile from the farthest bound in it, as of the last RefreshTiles, so hidden surfaces cost
  // nothing per pixel.
  bool CouldMatter(const PixelBox& box, std::array<double, 2> range, bool showing) const;
  void RefreshTiles();
  static constexpr int kTile = 16;  // the side of the tiles CouldMatter decides by

  // The background where no surface is certain, then every pixel's class, written into `pixels`
  // (the whole frame's, row by row) and counted into `counts`, with the band's first and worst.
  void Finish(Verification& counts, std::vector<PixelClass>& pixels);
  Rgb8 ImageColour(int x, int y) const;
  std::uint32_t width() const { return image_->width; }
  std::uint32_t height() const { return image_->height; }

 private:
  std::size_t Index(int x, int y) const { return std::size_t(y - row0_) * image_->width + std::size_t(x); }
  std::size_t TileOf(int x, int y) const { return std::size_t(((y - row0_) / kTile) * tiles_x_ + x / kTile); }
  // The per-pixel buffers are cleared a tile at a time, when a surface first reaches it: a tile
  // no surface reaches (the background's) costs no clearing, and Finish classes it in one sweep.
  void Use(std::size_t tile);
  double Gap(int x, int y) const { return used_[TileOf(x, y)] ? gap_[Index(x, y)] : 0.0; }
  // Finish's classing of one pixel, counted into `v`.
  void Count(int x, int y, PixelClass c, int distance, int& worst_distance, Verification& v) const;
  void FinishUsed(int x, int y, Verification& v, int& worst_distance, std::vector<PixelClass>& pixels);
  void FinishUnused(int x0, int x1, int y, Verification& v, int& worst_distance, std::vector<PixelClass>& pixels) const;
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
  // the smallest high end (Helly's theorem in one dimension): kept that way, the verdict does not
  // depend on the order of the offers. All zeros when nothing was offered.
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
  std::vector<char> is_dirty_;
  std::vector<char> used_;  // per tile: its pixels' gap_ and state_ are live (else all zeros)
};

}  // namespace twinraster::verify
