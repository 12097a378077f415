// Stages 1 to 5, vertex stage, clipping, viewport transform and set-up, for one chunk of a draw
// list at a time, so that memory stays bounded however large the scene. The result lists the
// chunk's primitives in the order the device rasterizes them: draws in list order, triangles in
// index order, a clipped triangle's fan in fan order (lavapipe), or its one polygon (SwiftShader).
// Parallel over vertices and over triangles; the result stays in ordered parts. The loop is one for
// both devices (chunk_loop.hpp); each device's assembly (cpu/lavapipe/assembly.hpp,
// cpu/swiftshader/assembly.hpp) sets its primitives up into its own scratch. It does not draw
// them (cpu_renderer.cpp does).
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/lavapipe/assembly.hpp"
#include "cpu/raster_rules.hpp"
#include "cpu/swiftshader/assembly.hpp"

#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// A piece of the draw list set up at once: whole draws [draw_begin, draw_end), or, for a draw with
// more triangles than a chunk holds, its triangles [triangle_begin, triangle_end) alone.
struct GeometryChunk {
  std::size_t draw_begin = 0, draw_end = 0;
  bool slice = false;  // one draw's triangles [triangle_begin, triangle_end)
  std::size_t triangle_begin = 0, triangle_end = 0;
  bool shade_vertices = true;  // false: a later slice of the draw the previous chunk shaded
};

// About this many triangles and vertices per chunk (a chunk of whole draws may hold fewer; one
// draw larger than this is sliced, its vertices shaded once for all its slices).
struct ChunkBudget {
  std::size_t triangles = std::size_t{1} << 16;
  std::size_t vertices = std::size_t{1} << 16;
};
std::vector<GeometryChunk> PlanChunks(const DrawList& list, const ChunkBudget& budget = {});

// Memory kept from one chunk, and one render, to the next: fresh memory costs a page fault per
// 4 KiB, which for small scenes is much of the work. `device` is one device's vertices and
// primitives (LavapipeScratch or SwiftShaderScratch); the rest is the shared loop's.
template <class DeviceScratch>
struct GeometryScratch {
  DeviceScratch device;
  std::vector<std::size_t> vertex_start;  // per draw of the shaded chunk, into device.vertices
  // bins[p][b]: indices into the primitives of part p of those whose box touches band b (kBandRows
  // rows), in order; binned as they are set up, while still in cache, so that each band's
  // rasterizer reads only the primitives it draws.
  std::vector<std::vector<std::vector<std::uint32_t>>> bins;

  std::size_t bytes() const {
    std::size_t total = device.bytes() + vertex_start.capacity() * sizeof(std::size_t);
    for (const auto& part : bins)
      for (const auto& bin : part) total += bin.capacity() * sizeof(std::uint32_t);
    return total;
  }
};
using LavapipeGeometry = GeometryScratch<LavapipeScratch>;
using SwiftShaderGeometry = GeometryScratch<SwiftShaderScratch>;

// Sets up one chunk into the scratch by the device's rules, the scratch's type saying which device
// (`rules.rasterizer` must agree), and, when band_count > 0, bins the primitives into scratch.bins.
// `clip`: when given, the positions another vertex stage computed (one vector per draw) replace
// this one's F · (p, 1). Defined beside each device's assembly, which the loop inlines.
void ProcessGeometry(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                     LavapipeGeometry& scratch, const std::vector<std::vector<glm::vec4>>* clip = nullptr,
                     unsigned band_count = 0);
void ProcessGeometry(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                     SwiftShaderGeometry& scratch, const std::vector<std::vector<glm::vec4>>* clip = nullptr,
                     unsigned band_count = 0);

// The whole list as one chunk set up by lavapipe's rules, for tests that want every triangle at
// once (SwiftShader's triangles are outlines).
TriangleChunks ProcessGeometry(const DrawList& list, unsigned threads, const RasterRules& rules = {});

}  // namespace twinraster::cpu
