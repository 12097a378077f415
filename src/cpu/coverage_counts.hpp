// For tests: how many triangles cover each pixel, with no depth test. Uses the same geometry and
// coverage stages as RenderOnCpu. Counts are kept apart by the sign of the snapped area (whether
// triangle setup swapped vertices 1 and 2), so a closed mesh can be checked: every pixel inside its
// silhouette is covered once by a triangle of each winding.
#pragma once

#include "chain/draw_list.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

struct CoverageCounts {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint32_t> kept;     // triangles drawn with their vertex order as given
  std::vector<std::uint32_t> swapped;  // triangles whose vertices 1 and 2 setup swapped

  std::size_t index(std::uint32_t x, std::uint32_t y) const { return std::size_t{y} * width + x; }
  std::uint32_t total(std::uint32_t x, std::uint32_t y) const { return kept[index(x, y)] + swapped[index(x, y)]; }
};

CoverageCounts CountCoverage(const DrawList& list, unsigned threads = 1);

}  // namespace twinraster::cpu
