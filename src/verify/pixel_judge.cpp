#include "verify/pixel_judge.hpp"

#include "verify/buffer_pool.hpp"

#include <algorithm>
#include <cstring>
#include <limits>

namespace twinraster::verify {

FrameJudge::FrameJudge(const Image& image, Rgb8 background, bool reversed_z, int row0, int row1)
    : image_(&image),
      background_(background),
      reversed_(reversed_z),
      row0_(row0),
      row1_(row1),
      clear_key_(reversed_z ? 0.0 : 1.0),
      tiles_x_(int((image.width + kTile - 1) / kTile)),
      tile_gap_(std::size_t(tiles_x_) * std::size_t((row1 - row0 + kTile - 1) / kTile)),
      is_dirty_(tile_gap_.size(), 0),
      used_(tile_gap_.size(), 0) {
  const std::size_t pixels = std::size_t{image.width} * std::size_t(row1 - row0);
  gap_ = BufferPool<double>::TakeAsLeft(pixels);
  state_ = BufferPool<State>::TakeAsLeft(pixels);
}

void FrameJudge::UseFirst(std::size_t tile) {
  used_[tile] = 1;
  const PixelBox box = TileBox(tile);
  for (int y = box.y0; y <= box.y1; ++y) {
    std::fill(gap_.begin() + std::ptrdiff_t(Index(box.x0, y)), gap_.begin() + std::ptrdiff_t(Index(box.x1, y)) + 1,
              0.0);
    std::fill(state_.begin() + std::ptrdiff_t(Index(box.x0, y)), state_.begin() + std::ptrdiff_t(Index(box.x1, y)) + 1,
              State{});
  }
}

FrameJudge::~FrameJudge() {
  BufferPool<double>::Give(std::move(gap_));
  BufferPool<State>::Give(std::move(state_));
}

PixelBox FrameJudge::TileBox(std::size_t tile) const {
  const int tx = int(tile) % tiles_x_, ty = int(tile) / tiles_x_;
  return {tx * kTile, row0_ + ty * kTile, std::min(int(image_->width), (tx + 1) * kTile) - 1,
          std::min(row1_, row0_ + (ty + 1) * kTile) - 1};
}

PixelBox FrameJudge::Clip(PixelBox box) const {
  box.y0 = std::max(box.y0, row0_);
  box.y1 = std::min(box.y1, row1_ - 1);
  return box;
}

bool FrameJudge::CouldMatter(const PixelBox& box, std::array<double, 2> range, bool showing) const {
  if (box.Empty()) return false;
  const double near_key = reversed_ ? -range[1] : range[0];
  if (!(near_key == near_key)) return true;  // NaN: judge it pixel by pixel
  for (int ty = (box.y0 - row0_) / kTile; ty <= (box.y1 - row0_) / kTile; ++ty) {
    for (int tx = box.x0 / kTile; tx <= box.x1 / kTile; ++tx) {
      const double gap = tile_gap_[std::size_t(ty) * std::size_t(tiles_x_) + std::size_t(tx)];
      if (showing ? clear_key_ - near_key >= gap : clear_key_ - near_key > gap) return true;
    }
  }
  return false;
}

void FrameJudge::RefreshTiles() {
  for (const std::uint32_t tile : dirty_) {
    const PixelBox box = TileBox(tile);
    double gap = std::numeric_limits<double>::infinity();
    for (int y = box.y0; y <= box.y1; ++y) {
      for (int x = box.x0; x <= box.x1; ++x) gap = std::min(gap, gap_[Index(x, y)]);
    }
    tile_gap_[tile] = gap;
    is_dirty_[tile] = 0;
  }
  dirty_.clear();
  lowered_ = 0;
}

void FrameJudge::Finish(Verification& v, std::vector<PixelClass>& pixels, const SettledRun& settled) {
  int worst_distance = 0;
  std::array<ColourRange, kTile> colours;
  for (int y = row0_; y < row1_; ++y) {  // in row order, for the first violation and the worst
    for (int x0 = 0; x0 < int(image_->width); x0 += kTile) {
      const int x1 = std::min(int(image_->width), x0 + kTile);
      if (!used_[TileOf(x0, y)]) {
        FinishUnused(x0, x1, y, v, worst_distance, pixels);
      } else if (settled && settled(y, x0, x1 - 1, colours.data())) {
        FinishSettled(x0, x1, y, colours.data(), v, worst_distance, pixels);
      } else {
        for (int x = x0; x < x1; ++x) FinishUsed(x, y, v, worst_distance, pixels);
      }
    }
  }
}

void FrameJudge::WriteReach(std::vector<Reach>& reach) const {
  for (int y = row0_; y < row1_; ++y) {
    Reach* out = reach.data() + std::size_t(y) * image_->width;
    for (int x = 0; x < int(image_->width); ++x) {
      if (!used_[TileOf(x, y)]) {
        out[x] = Reach::kNone;
        continue;
      }
      const std::size_t i = Index(x, y);
      out[x] = gap_[i] > 0 ? Reach::kCertain : state_[i].offers > 0 ? Reach::kMaybe : Reach::kNone;
    }
  }
}

void FrameJudge::FinishUsed(int x, int y, Verification& v, int& worst_distance, std::vector<PixelClass>& pixels) {
  const std::size_t i = Index(x, y);
  State& s = state_[i];
  if (s.offers > 0) ++v.covered;
  if (gap_[i] == 0) Offer(x, y, ColourRange::Exactly(background_));
  const bool disjoint = s.max_lo.r + s.hi_gap.r > 255 || s.max_lo.g + s.hi_gap.g > 255 || s.max_lo.b + s.hi_gap.b > 255;
  const int distance = 255 - s.closeness;
  if (s.background_closeness < 255) ++v.background_excluded;
  const PixelClass c = distance > 0 ? PixelClass::kViolation : disjoint ? PixelClass::kUncertain : PixelClass::kCertain;
  pixels[std::size_t(y) * image_->width + std::size_t(x)] = c;
  Count(x, y, c, distance, worst_distance, v);
  if (c == PixelClass::kUncertain && gap_[i] != 0 && !s.not_certain_line) ++v.uncertain_shared_edges;
}

// Pixels no surface reached: only the background is offered, so each is certain when it shows the
// background and a violation by its distance from it otherwise (what FinishUsed finds there too).
void FrameJudge::FinishUnused(int x0, int x1, int y, Verification& v, int& worst_distance,
                              std::vector<PixelClass>& pixels) const {
  PixelClass* out = pixels.data() + std::size_t(y) * image_->width;
  if (ShowsOnly(x0, x1, y, background_)) {  // the usual case, without classing pixel by pixel
    std::fill(out + x0, out + x1, PixelClass::kCertain);
    v.certain += std::uint64_t(x1 - x0);
    return;
  }
  const ColourRange background = ColourRange::Exactly(background_);
  for (int x = x0; x < x1; ++x) {
    const int distance = background.Distance(ImageColour(x, y));
    const PixelClass c = distance > 0 ? PixelClass::kViolation : PixelClass::kCertain;
    out[x] = c;
    Count(x, y, c, distance, worst_distance, v);
  }
}

// Pixels of a settled tile: `colours` is the only colour range offered at each and no background
// is (a surface is certain at each), so each is covered, never uncertain, and a violation by its
// distance from that range (what FinishUsed finds after the same offers).
void FrameJudge::FinishSettled(int x0, int x1, int y, const ColourRange* colours, Verification& v, int& worst_distance,
                               std::vector<PixelClass>& pixels) const {
  PixelClass* out = pixels.data() + std::size_t(y) * image_->width;
  const int n = x1 - x0;
  v.covered += std::uint64_t(n);
  // One exact colour over the run (a flat surface's), shown at every pixel: all certain at once.
  const ColourRange first = colours[0];
  if (first.lo == first.hi && std::all_of(colours, colours + n, [&](const ColourRange& c) { return c == first; }) &&
      ShowsOnly(x0, x1, y, first.lo)) {
    std::fill(out + x0, out + x1, PixelClass::kCertain);
    v.certain += std::uint64_t(n);
    if (first.Distance(background_) > 0) v.background_excluded += std::uint64_t(n);
    return;
  }
  for (int x = x0; x < x1; ++x) {
    const ColourRange& colour = colours[x - x0];
    if (colour.Distance(background_) > 0) ++v.background_excluded;
    const int distance = colour.Distance(ImageColour(x, y));
    const PixelClass c = distance > 0 ? PixelClass::kViolation : PixelClass::kCertain;
    out[x] = c;
    Count(x, y, c, distance, worst_distance, v);
  }
}

bool FrameJudge::ShowsOnly(int x0, int x1, int y, Rgb8 colour) const {
  // Whole pixels compared at once, alpha masked off, so that the compiler can vectorize the loop.
  const std::uint8_t rgb[4] = {colour.r, colour.g, colour.b, 0}, mask_bytes[4] = {255, 255, 255, 0};
  std::uint32_t expected = 0, mask = 0;
  std::memcpy(&expected, rgb, 4), std::memcpy(&mask, mask_bytes, 4);
  const std::uint8_t* p = image_->pixel(std::uint32_t(x0), std::uint32_t(y));
  std::uint32_t differ = 0;
  for (int x = x0; x < x1; ++x, p += 4) {
    std::uint32_t word = 0;
    std::memcpy(&word, p, 4);
    differ |= (word & mask) ^ expected;
  }
  return differ == 0;
}

void FrameJudge::Count(int x, int y, PixelClass c, int distance, int& worst_distance, Verification& v) const {
  if (c == PixelClass::kViolation) {
    ++v.violations;
    const Violation found{std::uint32_t(x), std::uint32_t(y), ImageColour(x, y), distance, {}};
    if (!v.first) v.first = found;
    if (distance > worst_distance) worst_distance = distance, v.worst = found;
  } else if (c == PixelClass::kUncertain) {
    ++v.uncertain;
  } else {
    ++v.certain;
  }
}

}  // namespace twinraster::verify
