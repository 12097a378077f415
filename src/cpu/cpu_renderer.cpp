#include "cpu/cpu_renderer.hpp"

#include "cpu/fragment_ops.hpp"
#include "cpu/geometry.hpp"
#include "cpu/parallel.hpp"
#include "cpu/rasterize.hpp"
#include "base/stopwatch.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>
#include <utility>

namespace twinraster {

namespace {

// The pipeline after validation; `clip` replaces the vertex stage when given.
Image Render(const DrawList& list, const ClipPositions* clip, const CpuOptions& options,
             CpuTimings* timings) {
  using namespace cpu;
  // More parts than bands would leave threads idle; the image does not depend on this number.
  const unsigned bands = (list.height + kBandRows - 1) / kBandRows;
  const unsigned threads = std::min(ResolveThreadCount(options.threads), bands);

  // Setup: vertex stage, clipping, viewport transform, triangle setup.
  Stopwatch clock;
  // Kept per thread from one render to the next (see GeometryScratch), up to 64 MiB.
  thread_local GeometryScratch scratch;
  ProcessGeometry(list, threads, scratch, clip);
  const TriangleChunks& triangles = scratch.triangles;
  const double setup_ms = clock.Lap();

  // Draw: every part clears its own bands and rasterizes all triangles, in order, over them.
  Framebuffer fb(list.width, list.height,
                 list.reversed_z ? DepthCompare::kGreater : DepthCompare::kLess);
  const std::uint32_t background = PackRgba(list.background);
  ParallelParts(threads, [&](unsigned part) {
    RasterizeBands(
        triangles, RowShare{threads, part}, static_cast<int>(list.height),
        [&](int row_begin, int row_end) { ClearRows(fb, row_begin, row_end, background); },
        [&](const TriangleSetup& t, int py, Span span) {
          ShadeSpan(fb, py, span, t.depth, t.colour);
        });
  });
  const double draw_ms = clock.Lap();

  // Readback: the colour attachment already is the Image.
  Image image = std::move(fb.colour);
  const double readback_ms = clock.Lap();

  if (scratch.bytes() > (std::size_t{64} << 20)) scratch = GeometryScratch{};
  if (timings != nullptr) *timings = {setup_ms, draw_ms, readback_ms, threads};
  return image;
}

}  // namespace

Image RenderOnCpu(const DrawList& list, const CpuOptions& options, CpuTimings* timings) {
  ValidateDrawList(list);
  return Render(list, nullptr, options, timings);
}

Image RasterizeClipSpace(const DrawList& list, const ClipPositions& clip, const CpuOptions& options,
                         CpuTimings* timings) {
  ValidateDrawList(list);
  if (clip.size() != list.draws.size()) throw std::invalid_argument("clip positions for the wrong number of draws");
  for (std::size_t d = 0; d < clip.size(); ++d) {
    if (clip[d].size() != list.meshes[list.draws[d].mesh].positions.size()) {
      throw std::invalid_argument("draw " + std::to_string(d) + ": clip positions do not match its mesh");
    }
  }
  return Render(list, &clip, options, timings);
}

}  // namespace twinraster
