#include "cpu/cpu_renderer.hpp"

#include "base/stopwatch.hpp"
#include "cpu/chunk_assembly.hpp"
#include "cpu/depth_tiles.hpp"
#include "cpu/fragment_ops.hpp"
#include "cpu/lavapipe/coverage.hpp"
#include "cpu/parallel.hpp"
#include "cpu/platform.hpp"
#include "cpu/thread_pool.hpp"

#include <algorithm>
#include <numeric>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>

namespace twinraster::cpu {

namespace {

// Where a chunk's bands are drawn: the scratch holding its binned primitives, the framebuffer and
// the depth tiles.
template <class DeviceScratch>
struct BandTarget {
  const GeometryScratch<DeviceScratch>& scratch;
  const CpuOptions& options;
  int height;
  Framebuffer& fb;
  DepthTiles& tiles;
  std::optional<std::uint32_t> clear;  // the colour each band is cleared to before it is drawn, if any
  bool refresh_tiles = true;           // false for the last chunk: no later one tests against them
};

// Each part rasterizes its own bands, each band's primitives in list order; hidden[part] counts
// what the depth tiles skipped. The per-primitive loop is kept as one lambda: it is the hot one, and
// GCC compiles it to fewer instructions than when it is split into functions. It is not inlined
// into the band loop: on its own it spills fewer registers for filled triangles, the costliest case
// (callgrind on scenes/bench/spheres-100k.json: 0.2 % fewer instructions; its wireframe 0.4 % more).
template <class DeviceScratch>
void DrawChunk(const BandTarget<DeviceScratch>& target, const RasterRules& rules, unsigned threads, unsigned bands,
               std::vector<std::uint64_t>& hidden) {
  const GeometryScratch<DeviceScratch>& scratch = target.scratch;
  const CpuOptions& options = target.options;
  const int height = target.height;
  Framebuffer& fb = target.fb;
  DepthTiles& tiles = target.tiles;
  ParallelParts(threads, [&](unsigned part) {
    const DenormalsAsZero denormals(rules.flush_denormals);
    std::uint64_t skipped = 0;  // counted here: a shared array written per triangle would ping-pong
    // The primitives of the chunk's bins for one band, drawn in order: parts[p][i] for each i in
    // bins[p][band], p = 0, 1, ...; rows(p, primitive, row_begin, row_end, on_span) rasterizes one.
    const auto draw_band = [&](unsigned band, const auto& parts, auto&& rows) __attribute__((noinline)) {
      const int band_begin = static_cast<int>(band) * kBandRows;
      const int band_end = std::min(height, band_begin + kBandRows);
      for (std::size_t p = 0; p < parts.size(); ++p) {
        for (const std::uint32_t i : scratch.bins[p][band]) {
          const auto& t = parts[p][i];
          const int row_begin = std::max(t.bounds.y0, band_begin), row_end = std::min(t.bounds.y1 + 1, band_end);
          if (options.depth_tiles && tiles.Hidden(t.bounds, t.depth, static_cast<int>(band), row_begin, row_end)) {
            ++skipped;
            continue;
          }
          rows(p, t, row_begin, row_end, [&](int py, Span span) {
            if constexpr (requires { t.smooth; }) {
              if (t.smooth) {
                ShadeSmoothSpan(fb, py, span, t.depth, scratch.device.SmoothPlanes(p, t.colour));
                tiles.MarkDrawn(py, span);
                return;
              }
            }
            ShadeSpan(fb, py, span, t.depth, t.colour);
            tiles.MarkDrawn(py, span);
          });
        }
      }
      if (options.depth_tiles && target.refresh_tiles) tiles.Refresh(fb, static_cast<int>(band));
    };
    // The device hands over its primitives once per chunk; this part then draws its bands.
    scratch.device.Draw(static_cast<int>(fb.width()), [&](const auto& parts, auto&& rows) {
      for (unsigned band = part; band < bands; band += threads) {
        if (target.clear) {
          const int band_begin = static_cast<int>(band) * kBandRows;
          ClearRows(fb, band_begin, std::min(height, band_begin + kBandRows), *target.clear);
        }
        draw_band(band, parts, rows);
      }
    });
    hidden[part] += skipped;
  });
}

// Clears every row, each part its own bands.
void ClearFrame(Framebuffer& fb, unsigned threads, std::uint32_t height, std::uint32_t background) {
  const TriangleChunks none;
  ParallelParts(threads, [&](unsigned part) {
    RasterizeBands(
        none, RowShare{threads, part}, static_cast<int>(height),
        [&](int row_begin, int row_end) { ClearRows(fb, row_begin, row_end, background); },
        [](const TriangleSetup&, int, Span) {});
  });
}

// Left to choose (threads 0), the twin draws a frame within kOneThreadPixels and
// kOneThreadTriangles on one thread: starting another and handing it parts costs more than its
// share (a one-scene process pays the thread's start, and its later unmappings then interrupt the
// other core), and in a batch the other core is busy with the GPU process or the last scene's
// files. Any count gives the same image.
unsigned ThreadsFor(const DrawList& list, unsigned requested, unsigned bands) {
  if (requested == 0 && std::uint64_t{list.width} * list.height <= kOneThreadPixels) {
    std::uint64_t triangles = 0;
    for (const DrawCall& draw : list.draws) triangles += list.meshes[draw.mesh].triangles.size();
    if (triangles <= kOneThreadTriangles) return 1;
  }
  // More parts than bands would leave threads idle.
  return std::min(ResolveThreadCount(requested), bands);
}

// The pipeline after validation, by one device's rules (DeviceScratch: LavapipeScratch or
// SwiftShaderScratch); `clip` replaces the vertex stage when given. The list streams through in
// chunks (chunk_assembly.hpp): each chunk is set up by all threads, then rasterized by all
// threads, each over its own bands, before the next chunk is set up, so memory stays bounded.
// Every band sees every triangle in list order whatever the chunking and the thread count.
template <class DeviceScratch>
Image RenderBy(const DrawList& list, const ClipPositions* clip, const CpuOptions& options, CpuTimings* timings) {
  const unsigned bands = (list.height + kBandRows - 1) / kBandRows;
  const unsigned threads = ThreadsFor(list, options.threads, bands);
  const KeepPoolSpinning stages_follow;
  // Kept per calling thread from one render to the next (see GeometryScratch). Used through a
  // reference: in a lambda run by a pool worker, the name itself would mean the worker's own.
  thread_local GeometryScratch<DeviceScratch> per_thread_scratch;
  GeometryScratch<DeviceScratch>& scratch = per_thread_scratch;
  ChunkBudget budget;
  if (options.chunk_triangles != 0) budget = ChunkBudget{options.chunk_triangles, options.chunk_triangles};
  const std::vector<GeometryChunk> chunks = PlanChunks(list, budget);

  Stopwatch clock;
  double setup_ms = 0, draw_ms = 0;
  // One chunk clears each band just before drawing it, while its rows are in the cache, and needs
  // depth only for the band each thread is drawing; several chunks (or none) clear the whole frame
  // first and keep its whole depth, which the next chunk tests against.
  const bool one_chunk = chunks.size() == 1;
  const std::optional<std::uint32_t> clear_in_draw =
      one_chunk ? std::optional(PackRgba(list.background)) : std::nullopt;
  Framebuffer fb(list.width, list.height, list.reversed_z ? DepthCompare::kGreater : DepthCompare::kLess,
                 one_chunk ? threads * kBandRows : list.height);
  if (!clear_in_draw) ClearFrame(fb, threads, list.height, PackRgba(list.background));
  draw_ms += clock.Lap();

  DepthTiles tiles(list.width, list.height, fb.compare);
  std::vector<std::uint64_t> hidden(threads, 0);  // per part
  BandTarget<DeviceScratch> target{scratch, options, static_cast<int>(list.height), fb, tiles, clear_in_draw};
  for (const GeometryChunk& chunk : chunks) {
    target.refresh_tiles = &chunk != &chunks.back();
    // Setup: vertex stage, clipping, viewport transform, triangle (or line) setup, binning into bands.
    ProcessGeometry(list, chunk, threads, options.rules, scratch, clip, bands);
    setup_ms += clock.Lap();
    DrawChunk(target, options.rules, threads, bands, hidden);
    target.clear.reset();
    draw_ms += clock.Lap();
  }

  // Readback: the colour attachment already is the Image.
  Image image = std::move(fb.colour);
  const double readback_ms = clock.Lap();

  // A sliced giant mesh may have grown the scratch; don't keep that much between renders.
  if (scratch.bytes() > (std::size_t{64} << 20)) scratch = GeometryScratch<DeviceScratch>{};
  if (timings != nullptr) {
    *timings = {setup_ms, draw_ms, readback_ms, threads,
                std::accumulate(hidden.begin(), hidden.end(), std::uint64_t{0})};
  }
  return image;
}

// The one choice of device: everything after it is that device's set-up and coverage.
Image Render(const DrawList& list, const ClipPositions* clip, const CpuOptions& options, CpuTimings* timings) {
  if (options.rules.rasterizer == Rasterizer::kSwiftShader)
    return RenderBy<SwiftShaderScratch>(list, clip, options, timings);
  return RenderBy<LavapipeScratch>(list, clip, options, timings);
}

}  // namespace

TwinLimits TwinDeviceLimits(const RasterRules& rules) {
  return {.subpixel_bits = SubpixelBitsOf(rules), .strict_lines = true};
}

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

}  // namespace twinraster::cpu
