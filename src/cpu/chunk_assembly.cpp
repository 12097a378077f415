#include "cpu/chunk_assembly.hpp"

#include <algorithm>

namespace twinraster::cpu {

std::vector<GeometryChunk> PlanChunks(const DrawList& list, const ChunkBudget& budget) {
  std::vector<GeometryChunk> chunks;
  const std::size_t n = list.draws.size();
  const auto triangles_of = [&](std::size_t d) { return list.meshes[list.draws[d].mesh].triangles.size(); };
  const auto vertices_of = [&](std::size_t d) { return list.meshes[list.draws[d].mesh].positions.size(); };
  for (std::size_t d = 0; d < n;) {
    const std::size_t t = triangles_of(d);
    if (t > budget.triangles) {
      for (std::size_t begin = 0; begin < t; begin += budget.triangles) {
        chunks.push_back(GeometryChunk{.draw_begin = d,
                                       .draw_end = d + 1,
                                       .slice = true,
                                       .triangle_begin = begin,
                                       .triangle_end = std::min(t, begin + budget.triangles),
                                       .shade_vertices = begin == 0});
      }
      ++d;
      continue;
    }
    // Whole draws while both budgets hold; the first draw always fits.
    const std::size_t begin = d;
    std::size_t triangles = 0, vertices = 0;
    while (d < n && triangles_of(d) <= budget.triangles &&
           (d == begin ||
            (triangles + triangles_of(d) <= budget.triangles && vertices + vertices_of(d) <= budget.vertices))) {
      triangles += triangles_of(d);
      vertices += vertices_of(d);
      ++d;
    }
    chunks.push_back(GeometryChunk{.draw_begin = begin, .draw_end = d});
  }
  return chunks;
}

TriangleChunks ProcessGeometry(const DrawList& list, unsigned threads, const RasterRules& rules) {
  LavapipeGeometry scratch;
  ProcessGeometry(list, GeometryChunk{.draw_begin = 0, .draw_end = list.draws.size()}, threads, rules, scratch);
  return std::move(scratch.device.triangles);
}

}  // namespace twinraster::cpu
