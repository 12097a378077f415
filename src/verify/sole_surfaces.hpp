// Pass 2's settled tiles: a tile whose every pixel has a surface certain to be written there, and
// that pass 2 finds reached by one surface only, or by two that offer one and the same exact colour,
// allows at each pixel only what those surfaces offer there. Its pixels get no offers one by one;
// Finish classes them against those colours alone. It does not decide coverage, depth or colours
// (coverage_shapes.hpp, pixel_judge.hpp do). A tile that another surface then reaches gets the held
// surfaces' offers pixel by pixel after all, which changes nothing: a pixel's class does not
// depend on the order of its offers.
#pragma once

#include "verify/coverage_shapes.hpp"
#include "verify/pixel_judge.hpp"

#include <array>
#include <cstdint>
#include <type_traits>
#include <variant>
#include <vector>

namespace twinraster::verify {

// Why it holds: every surface certain at a pixel of the tile is one that pass 2 finds reaching the
// tile (its depth there is within the depth it is culled by), visits at that pixel (pass 1 did) and
// finds able to show (nothing is nearer for sure than its own far depth). So each pixel gets at
// least one offer from the held surfaces, and only theirs.
class SoleSurfaces {
 public:
  explicit SoleSurfaces(FrameJudge& judge) : judge_(judge), tiles_(judge.Tiles()) {}

  // Pass 2's word on the row run of `shape` at (x, y) in one tile, which the tile's depth bound
  // already lets it reach and which the tile does not hold yet (HeldBy is asked first): whether the shape must offer
  // there pixel by pixel (false: the tile holds it back). `serial` numbers the shapes of the frame, one each, in the
  // order they are offered; `box` is the part of the frame the shape is scanned in.
  template <class Shape>
  bool Keep(const Shape& shape, Rgb8 flat, const PixelBox& box, int x, int y, std::uint64_t serial) {
    const std::size_t tile = judge_.TileOf(x, y);
    Tile& t = tiles_[tile];
    if (t.mixed) return true;
    bool exact = true;  // whether every pixel gets the one colour `flat`
    if constexpr (std::is_same_v<Shape, TriangleShape>) exact = !shape.lit();
    const bool holds =
        judge_.TileCertain(tile) &&
        (t.count == 0 || (t.count == 1 && exact && held_[t.held[0]].exact && held_[t.held[0]].flat == flat));
    if (!holds) {
      Release(tile);
      return true;
    }
    t.held[t.count++] = held_.size();
    held_.push_back({shape, box, flat, serial, exact});
    return false;
  }

  // Whether the tile holds back the shape `serial`: its runs there need no other test.
  bool HeldBy(std::size_t tile, std::uint64_t serial) const {
    const Tile& t = tiles_[tile];
    for (std::uint8_t i = 0; i < t.count; ++i) {
      if (held_[t.held[i]].serial == serial) return true;
    }
    return false;
  }

  // FrameJudge::SettledRun: the colours allowed at each pixel of the run, if its tile is settled.
  bool Settled(int y, int x0, int x1, ColourRange* colours) const;

 private:
  struct Held {
    std::variant<TriangleShape, LineShape> shape;
    PixelBox box;
    Rgb8 flat;
    std::uint64_t serial;
    bool exact;
  };
  struct Tile {
    std::array<std::size_t, 2> held{};  // in held_
    std::uint8_t count = 0;
    bool mixed = false;  // reached by surfaces that cannot settle it: judged pixel by pixel
  };

  // The tile cannot be settled: its held surfaces offer at each pixel as Scan would have.
  void Release(std::size_t tile);

  FrameJudge& judge_;
  std::vector<Tile> tiles_;
  std::vector<Held> held_;
};

}  // namespace twinraster::verify
