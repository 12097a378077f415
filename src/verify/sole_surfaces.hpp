// Pass 2's whole tiles: a tile that the first surface to reach it covers whole, certainly, and
// that no other surface reaches shows that surface at every pixel with nothing else allowed, so its
// pixels get no offers one by one and Finish classes them against that surface's colours alone.
// It does not decide coverage, depth or colours (coverage_shapes.hpp, pixel_judge.hpp do), and a
// tile that a second surface reaches gets the first one's offers pixel by pixel after all, which
// changes nothing: a pixel's verdict does not depend on the order of its offers.
#pragma once

#include "verify/coverage_shapes.hpp"
#include "verify/pixel_judge.hpp"

#include <cstdint>
#include <type_traits>
#include <vector>

namespace twinraster::verify {

// Why one surface suffices: pass 1 left a certain surface at every pixel of the tile, and any
// surface that was certain at a pixel is one pass 2 finds reaching the tile (its depth range bounds
// its depth there). If the first and only surface reaching the tile covers it whole, it was the
// nearest certain one at every pixel, so it may show at each, and nothing else may.
class SoleSurfaces {
 public:
  explicit SoleSurfaces(FrameJudge& judge) : judge_(judge), reached_(judge.Tiles(), 0), held_at_(judge.Tiles(), -1) {}

  // Pass 2's word on the row run of `shape` at (x, y) in one tile, which the tile's depth bound
  // already lets it reach: whether the shape must offer there pixel by pixel (false: the tile holds
  // it back). `serial` numbers the shapes of the frame, one each, in the order they are offered.
  template <class Shape>
  bool Keep(const Shape& shape, Rgb8 flat, const PixelBox& box, int x, int y, std::uint64_t serial) {
    const std::size_t tile = judge_.TileOf(x, y);
    if (reached_[tile] == 2) return true;
    if (reached_[tile] == 1) {
      if (HeldBy(tile, serial)) return false;
      Release(tile);
      return true;
    }
    reached_[tile] = 2;
    if constexpr (std::is_same_v<Shape, TriangleShape>) {
      if (judge_.TileCertain(tile) && CoversWhole(shape, box, judge_.TileBox(tile))) {
        Hold(tile, shape, flat, serial);
        return false;
      }
    }
    return true;
  }

  // Whether the tile holds back the shape `serial`: its runs there need no other test.
  bool HeldBy(std::size_t tile, std::uint64_t serial) const {
    return reached_[tile] == 1 && held_[std::size_t(held_at_[tile])].serial == serial;
  }

  // FrameJudge::SettledRun: the colours of the run's one surface, if a surface settles its tile.
  bool Settled(int y, int x0, int x1, ColourRange* colours) const;

 private:
  struct Held {
    TriangleShape shape;
    Rgb8 flat;
    std::uint64_t serial;
  };

  // Whether Scan finds `shape` covering every pixel of `tile` certainly (Coverage::kIn).
  static bool CoversWhole(const TriangleShape& shape, const PixelBox& box, const PixelBox& tile);
  void Hold(std::size_t tile, const TriangleShape& shape, Rgb8 flat, std::uint64_t serial);
  // A second surface reached the tile: the held one offers at each pixel as Scan would have.
  void Release(std::size_t tile);

  FrameJudge& judge_;
  std::vector<std::uint8_t> reached_;  // per tile: 0 none yet, 1 the held surface only, 2 more or none held
  std::vector<std::int32_t> held_at_;  // per tile: its held surface in held_, or -1
  std::vector<Held> held_;
};

}  // namespace twinraster::verify
