// Which triangle of a mesh lies across each edge of each triangle, from the mesh's indices alone:
// pass 1 uses it to find the centres near a shared edge that one of its two triangles covers
// whichever way the edge moves. It knows nothing of positions, depths or pixels.
#pragma once

#include "chain/draw_list.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::verify {

struct Neighbour {
  std::int32_t triangle = -1;  // -1: a border, or an edge more than two triangles share
  std::int32_t edge = -1;      // the edge's index in that triangle
};

// For each triangle's edge i (tri[i] -> tri[i + 1]), the one other triangle sharing it.
std::vector<std::array<Neighbour, 3>> MeshNeighbours(const DrawMesh& mesh);

}  // namespace twinraster::verify
