// The loop both devices' set-up runs in (chunk_assembly.hpp): the vertex stage over a chunk's
// vertices, then per triangle its lighting and the device's assembly, in parts over threads, each
// part binning what it set up. A template over the device's assembly (LavapipeAssembly,
// SwiftShaderAssembly: Shade, Flat, Smooth, Wireframe), instantiated in that assembly's own file so
// that GCC inlines the assembly into the hot loop. It holds no device's arithmetic.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/chunk_assembly.hpp"
#include "cpu/lighting.hpp"
#include "cpu/parallel.hpp"
#include "cpu/platform.hpp"
#include "cpu/vertex_stage.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cstddef>
#include <vector>

namespace twinraster::cpu {

// Threads only pay off for enough work; the result does not depend on their number.
inline unsigned PartsFor(unsigned threads, std::size_t items, std::size_t per_part) {
  return static_cast<unsigned>(std::min<std::size_t>(threads, 1 + items / per_part));
}

// The draw i with start[i] <= global < start[i + 1].
inline std::size_t DrawOf(const std::vector<std::size_t>& start, std::size_t global) {
  return static_cast<std::size_t>(std::upper_bound(start.begin(), start.end(), global) - start.begin()) - 1;
}

// A chunk's draws, numbered from 0 (draw chunk.draw_begin + i), and its triangles numbered across
// them, so that both loops split evenly.
struct ChunkDraws {
  ChunkDraws(const DrawList& l, const GeometryChunk& c)
      : list(l), chunk(c), count(c.draw_end - c.draw_begin), triangle_start(count + 1, 0) {
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t triangles = chunk.slice ? chunk.triangle_end - chunk.triangle_begin : mesh(i).triangles.size();
      triangle_start[i + 1] = triangle_start[i] + triangles;
    }
  }
  const DrawMesh& mesh(std::size_t i) const { return list.meshes[list.draws[chunk.draw_begin + i].mesh]; }

  const DrawList& list;
  const GeometryChunk& chunk;
  std::size_t count;
  std::vector<std::size_t> triangle_start;  // draw i's triangles are [triangle_start[i], triangle_start[i + 1])
  std::size_t first_triangle = chunk.slice ? chunk.triangle_begin : 0;  // the first's index in its mesh
};

// Vertex stage (and the device's viewport transform and outcodes) for every draw's vertices, into
// the assembly's vertices from scratch.vertex_start[i] for draw i.
template <class Assembly>
void ShadeVertices(const ChunkDraws& draws, const Assembly& assembly, const std::vector<std::vector<glm::vec4>>* clip,
                   unsigned threads, bool flush_denormals, GeometryScratch<typename Assembly::Scratch>& scratch) {
  const DrawList& list = draws.list;
  const std::size_t draw_begin = draws.chunk.draw_begin;
  auto& vertices = scratch.device.vertices;
  std::vector<std::size_t>& vertex_start = scratch.vertex_start;
  vertex_start.assign(draws.count + 1, 0);
  for (std::size_t i = 0; i < draws.count; ++i) vertex_start[i + 1] = vertex_start[i] + draws.mesh(i).positions.size();
  vertices.resize(vertex_start[draws.count]);
  ParallelFor(
      PartsFor(threads, vertices.size(), 8192), vertices.size(), [&](std::size_t begin, std::size_t end, unsigned) {
        const DenormalsAsZero denormals(flush_denormals);
        for (std::size_t g = begin; g < end;) {
          const std::size_t i = DrawOf(vertex_start, g);
          const std::size_t d = draw_begin + i;
          const DrawMesh& mesh = draws.mesh(i);
          const std::size_t stop = std::min(end, vertex_start[i + 1]);
          for (; g < stop; ++g) {
            const std::size_t v = g - vertex_start[i];
            vertices[g] = assembly.Shade(clip ? (*clip)[d][v] : VertexStage(list.draws[d].F, mesh.positions[v]));
          }
        }
      });
}

// Empties each part's output and bins and reserves its share. Here, in the calling thread: a
// worker's fresh memory would cost a page fault per 4 KiB on every render; with a reused scratch
// there is usually nothing to allocate.
template <class DeviceScratch>
void ReserveParts(std::size_t triangle_count, unsigned parts, unsigned band_count, bool wireframe,
                  GeometryScratch<DeviceScratch>& scratch) {
  scratch.bins.resize(parts);
  for (unsigned part = 0; part < parts; ++part) {
    scratch.bins[part].resize(band_count);
    for (auto& bin : scratch.bins[part]) bin.clear();
  }
  scratch.device.Reserve(parts, wireframe, [&](unsigned part) {
    return triangle_count * (part + 1) / parts - triangle_count * part / parts;
  });
}

// The shared loop: a later slice of one draw reuses the vertices its first slice shaded, and each
// part of the triangles keeps its slice in order. The per-triangle loop is kept whole here: it is
// the hot one, and GCC compiles it to fewer instructions than when it is split into functions.
template <class Assembly>
void AssembleChunk(const ChunkDraws& draws, const Assembly& assembly, const std::vector<std::vector<glm::vec4>>* clip,
                   unsigned threads, const RasterRules& rules, unsigned band_count,
                   GeometryScratch<typename Assembly::Scratch>& scratch) {
  const DrawList& list = draws.list;
  const GeometryChunk& chunk = draws.chunk;
  if (chunk.shade_vertices) ShadeVertices(draws, assembly, clip, threads, rules.flush_denormals, scratch);

  const std::vector<std::size_t>& triangle_start = draws.triangle_start;
  const std::size_t first_triangle = draws.first_triangle;
  const std::size_t triangle_count = triangle_start[draws.count];
  const unsigned triangle_parts = PartsFor(threads, triangle_count, 2048);
  const bool wireframe = list.wireframe;
  ReserveParts(triangle_count, triangle_parts, band_count, wireframe, scratch);
  const auto& vertices = scratch.device.vertices;
  const std::vector<std::size_t>& vertex_start = scratch.vertex_start;
  ParallelFor(triangle_parts, triangle_count, [&](std::size_t begin, std::size_t end, unsigned part) {
    const DenormalsAsZero denormals(rules.flush_denormals);
    for (std::size_t g = begin; g < end;) {
      const std::size_t i = DrawOf(triangle_start, g);
      const DrawMesh& mesh = draws.mesh(i);
      const auto* base = vertices.data() + vertex_start[i];
      // A corner's base colour: its vertex's when the mesh has vertex colours, else the triangle's
      // (the vertex shader reads the same, triangle.vert's VERTEX_COLOURS).
      const Rgb8* vertex_colours = mesh.vertex_colours.empty() ? nullptr : mesh.vertex_colours.data();
      const std::size_t stop = std::min(end, triangle_start[i + 1]);
      for (; g < stop; ++g) {
        const std::size_t t = first_triangle + g - triangle_start[i];
        const auto& tri = mesh.triangles[t];
        const auto corner_base = [&](std::size_t k) {
          return vertex_colours ? vertex_colours[tri[k]] : mesh.colours[t];
        };
        if (wireframe) {
          assembly.Wireframe({base + tri[0], base + tri[1], base + tri[2]}, PackRgba(mesh.colours[t]), part);
        } else if (mesh.shading == Shading::kFlat) {
          // Lit once, at the provoking vertex (corner 0), whose flat output fills the triangle.
          const LitInstance& lit = list.lighting->instances[chunk.draw_begin + i];
          const glm::vec3 colour =
              LightVertex(*list.lighting, lit, mesh.positions[tri[0]], mesh.normals[t][0], corner_base(0));
          assembly.Flat({base + tri[0], base + tri[1], base + tri[2]}, PackUnorm(colour), part);
        } else if (mesh.shading == Shading::kGouraud) {
          const LitInstance& lit = list.lighting->instances[chunk.draw_begin + i];
          std::array<glm::vec3, 3> colours;
          for (std::size_t k = 0; k < 3; ++k) {
            colours[k] = LightVertex(*list.lighting, lit, mesh.positions[tri[k]], mesh.normals[t][k], corner_base(k));
          }
          assembly.Smooth({base + tri[0], base + tri[1], base + tri[2]}, colours, part);
        } else if (vertex_colours) {
          // Unlit vertex colours: k / 255 at each corner, interpolated as Gouraud colours are.
          const std::array<glm::vec3, 3> colours = {BaseColour(vertex_colours[tri[0]]),
                                                    BaseColour(vertex_colours[tri[1]]),
                                                    BaseColour(vertex_colours[tri[2]])};
          assembly.Smooth({base + tri[0], base + tri[1], base + tri[2]}, colours, part);
        } else {
          assembly.Flat({base + tri[0], base + tri[1], base + tri[2]}, PackRgba(mesh.colours[t]), part);
        }
      }
    }
    if (band_count != 0) scratch.device.Bin(part, scratch.bins[part]);
  });
}

// One chunk set up by `assembly`'s device: what each device's ProcessGeometry calls.
template <class Assembly>
void SetUpChunk(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                const Assembly& assembly, GeometryScratch<typename Assembly::Scratch>& scratch,
                const std::vector<std::vector<glm::vec4>>* clip, unsigned band_count) {
  const ChunkDraws draws(list, chunk);
  AssembleChunk(draws, assembly, clip, threads, rules, band_count, scratch);
}

}  // namespace twinraster::cpu
