#include "verify/sole_surfaces.hpp"

#include <algorithm>

namespace twinraster::verify {

bool SoleSurfaces::CoversWhole(const TriangleShape& shape, const PixelBox& box, const PixelBox& tile) {
  if (tile.x0 < box.x0 || tile.x1 > box.x1 || tile.y0 < box.y0 || tile.y1 > box.y1) return false;
  for (int y = tile.y0; y <= tile.y1; ++y) {
    // As Scan: its pixels within the row's reach and its inside span are visited as covered.
    const TriangleShape::RowSpans spans = shape.Spans(y);
    const std::array<int, 2> reach = spans.reach, inside = spans.inside;
    if (tile.x0 < std::max(reach[0], inside[0]) || tile.x1 > std::min(reach[1], inside[1])) return false;
  }
  return true;
}

void SoleSurfaces::Hold(std::size_t tile, const TriangleShape& shape, Rgb8 flat, std::uint64_t serial) {
  held_at_[tile] = std::int32_t(held_.size());
  held_.push_back({shape, flat, serial});
  reached_[tile] = 1;
}

void SoleSurfaces::Release(std::size_t tile) {
  const Held& held = held_[std::size_t(held_at_[tile])];
  const PixelBox box = judge_.TileBox(tile);
  for (int y = box.y0; y <= box.y1; ++y) {
    for (int x = box.x0; x <= box.x1; ++x) {
      const glm::dvec2 centre(x + 0.5, y + 0.5);
      if (judge_.MayShow(x, y, held.shape.Depth(centre))) judge_.Offer(x, y, held.shape.Colour(centre, held.flat));
    }
  }
  held_at_[tile] = -1;
  reached_[tile] = 2;
}

bool SoleSurfaces::Settled(int y, int x0, int x1, ColourRange* colours) const {
  const std::size_t tile = judge_.TileOf(x0, y);
  if (reached_[tile] != 1) return false;
  const Held& held = held_[std::size_t(held_at_[tile])];
  for (int x = x0; x <= x1; ++x) colours[x - x0] = held.shape.Colour(glm::dvec2(x + 0.5, y + 0.5), held.flat);
  return true;
}

}  // namespace twinraster::verify
