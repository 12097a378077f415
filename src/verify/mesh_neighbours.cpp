#include "verify/mesh_neighbours.hpp"

#include <algorithm>

namespace twinraster::verify {

std::vector<std::array<Neighbour, 3>> MeshNeighbours(const DrawMesh& mesh) {
  // Every edge keyed by its two vertices, sorted so that the triangles sharing one are adjacent.
  struct Side {
    std::uint64_t key;
    Neighbour at;
  };
  std::vector<Side> sides;
  sides.reserve(mesh.triangles.size() * 3);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::size_t i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[t][i], b = mesh.triangles[t][(i + 1) % 3];
      sides.push_back({(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b), {std::int32_t(t), std::int32_t(i)}});
    }
  }
  std::sort(sides.begin(), sides.end(), [](const Side& l, const Side& r) { return l.key < r.key; });
  std::vector<std::array<Neighbour, 3>> out(mesh.triangles.size());
  for (std::size_t s = 0; s < sides.size();) {
    std::size_t end = s + 1;
    while (end < sides.size() && sides[end].key == sides[s].key) ++end;
    if (end - s == 2) {
      const Neighbour p = sides[s].at, q = sides[s + 1].at;
      out[std::size_t(p.triangle)][std::size_t(p.edge)] = q;
      out[std::size_t(q.triangle)][std::size_t(q.edge)] = p;
    }
    s = end;
  }
  return out;
}

}  // namespace twinraster::verify
