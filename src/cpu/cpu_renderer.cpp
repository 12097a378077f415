#include "cpu/cpu_renderer.hpp"

#include "cpu/fragment_ops.hpp"
#include "cpu/geometry.hpp"
#include "cpu/parallel.hpp"
#include "cpu/rasterize.hpp"

#include <algorithm>
#include <bit>
#include <chrono>
#include <cstring>

namespace twinraster {

namespace {

double MillisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

Image RenderOnCpu(const DrawList& list, const CpuOptions& options, CpuTimings* timings) {
  using namespace cpu;
  ValidateDrawList(list);
  // More parts than rows would leave threads idle; the image does not depend on this number.
  const unsigned threads = std::min(ResolveThreadCount(options.threads), list.height);

  // Setup: vertex stage, clipping, viewport transform, triangle setup.
  auto start = std::chrono::steady_clock::now();
  const std::vector<TriangleSetup> triangles = ProcessGeometry(list, threads);
  const double setup_ms = MillisecondsSince(start);

  // Draw: clear, then every part rasterizes all triangles in order over its own rows.
  start = std::chrono::steady_clock::now();
  Framebuffer fb(list.width, list.height, PackRgba(list.background));
  ParallelParts(threads, [&](unsigned part) {
    const RowShare share{threads, part};
    for (const TriangleSetup& t : triangles) {
      ForEachSpan(t, share, [&](int py, Span span) { ShadeSpan(fb, py, span, t.depth, t.colour); });
    }
  });
  const double draw_ms = MillisecondsSince(start);

  // Readback: the colour words already hold the RGBA bytes in memory order.
  start = std::chrono::steady_clock::now();
  Image image(list.width, list.height);
  std::memcpy(image.rgba.data(), fb.colour.data(), image.rgba.size());
  const double readback_ms = MillisecondsSince(start);

  if (timings != nullptr) *timings = {setup_ms, draw_ms, readback_ms};
  return image;
}

}  // namespace twinraster
