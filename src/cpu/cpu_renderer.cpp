#include "cpu/cpu_renderer.hpp"

#include "cpu/fragment_ops.hpp"
#include "cpu/geometry.hpp"
#include "cpu/parallel.hpp"
#include "cpu/rasterize.hpp"

#include <algorithm>
#include <chrono>
#include <utility>

namespace twinraster {

namespace {

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Image RenderOnCpu(const DrawList& list, const CpuOptions& options, CpuTimings* timings) {
  using namespace cpu;
  ValidateDrawList(list);
  // More parts than bands would leave threads idle; the image does not depend on this number.
  const unsigned bands = (list.height + kBandRows - 1) / kBandRows;
  const unsigned threads = std::min(ResolveThreadCount(options.threads), bands);

  // Setup: vertex stage, clipping, viewport transform, triangle setup.
  auto start = std::chrono::steady_clock::now();
  const std::vector<TriangleSetup> triangles = ProcessGeometry(list, threads);
  const double setup_ms = MillisecondsSince(start);

  // Draw: every part clears its own bands and rasterizes all triangles, in order, over them.
  start = std::chrono::steady_clock::now();
  Framebuffer fb(list.width, list.height);
  const std::uint32_t background = PackRgba(list.background);
  ParallelParts(threads, [&](unsigned part) {
    RasterizeBands(
        triangles, RowShare{threads, part}, static_cast<int>(list.height),
        [&](int row_begin, int row_end) { ClearRows(fb, row_begin, row_end, background); },
        [&](const TriangleSetup& t, int py, Span span) { ShadeSpan(fb, py, span, t.depth, t.colour); });
  });
  const double draw_ms = MillisecondsSince(start);

  // Readback: the colour attachment already is the Image.
  start = std::chrono::steady_clock::now();
  Image image = std::move(fb.colour);
  const double readback_ms = MillisecondsSince(start);

  if (timings != nullptr) *timings = {setup_ms, draw_ms, readback_ms};
  return image;
}

}  // namespace twinraster
