#include "verify/sole_surfaces.hpp"

#include "verify/scan.hpp"

#include <algorithm>

namespace twinraster::verify {

void SoleSurfaces::Release(std::size_t tile) {
  Tile& t = tiles_[tile];
  const PixelBox whole = judge_.TileBox(tile);
  for (std::uint8_t i = 0; i < t.count; ++i) {
    const Held& held = held_[t.held[i]];
    const PixelBox box{std::max(whole.x0, held.box.x0), std::max(whole.y0, held.box.y0),
                       std::min(whole.x1, held.box.x1), std::min(whole.y1, held.box.y1)};
    // What pass 2 would have offered, less the runs its depth test skips: there it may show nowhere.
    std::visit(
        [&](const auto& shape) {
          constexpr bool kLine = std::is_same_v<std::decay_t<decltype(shape)>, LineShape>;
          Scan(
              shape, box, [](int, int, int) { return true; },
              [&](int x, int y, glm::dvec2 p, Coverage c) {
                if (judge_.MayShow(x, y, shape.Depth(p)))
                  judge_.Offer(x, y, shape.Colour(p, held.flat), kLine && c == Coverage::kIn);
              });
        },
        held.shape);
  }
  t.count = 0;
  t.mixed = true;
}

bool SoleSurfaces::Settled(int y, int x0, int x1, ColourRange* colours) const {
  const Tile& t = tiles_[judge_.TileOf(x0, y)];
  if (t.mixed || t.count == 0) return false;
  const Held& held = held_[t.held[0]];
  if (held.exact) {
    std::fill(colours, colours + (x1 - x0 + 1), ColourRange::Exactly(held.flat));
    return true;
  }
  const TriangleShape& shape = std::get<TriangleShape>(held.shape);  // the one way to vary: light
  for (int x = x0; x <= x1; ++x) colours[x - x0] = shape.Colour(glm::dvec2(x + 0.5, y + 0.5), held.flat);
  return true;
}

}  // namespace twinraster::verify
