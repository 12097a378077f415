#include "cpu/coverage_counts.hpp"

#include "cpu/chunk_assembly.hpp"
#include "cpu/lavapipe/coverage.hpp"
#include "cpu/parallel.hpp"

namespace twinraster::cpu {

CoverageCounts CountCoverage(const DrawList& list, unsigned threads) {
  ValidateDrawList(list);
  threads = ResolveThreadCount(threads);
  const TriangleChunks triangles = ProcessGeometry(list, threads);
  CoverageCounts counts;
  counts.width = list.width;
  counts.height = list.height;
  counts.kept.assign(std::size_t{list.width} * list.height, 0);
  counts.swapped.assign(std::size_t{list.width} * list.height, 0);
  ParallelParts(threads, [&](unsigned part) {
    RasterizeBands(
        triangles, RowShare{threads, part}, static_cast<int>(list.height), [](int, int) {},
        [&](const TriangleSetup& t, int py, Span span) {
          std::vector<std::uint32_t>& target = t.swapped ? counts.swapped : counts.kept;
          for (int px = span.begin; px < span.end; ++px) {
            ++target[counts.index(static_cast<std::uint32_t>(px), static_cast<std::uint32_t>(py))];
          }
        });
  });
  return counts;
}

}  // namespace twinraster::cpu
