#include "cpu/geometry.hpp"

#include "cpu/parallel.hpp"
#include "cpu/vertex_stage.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace twinraster::cpu {

std::uint32_t PackRgba(Rgb8 colour) {
  return std::bit_cast<std::uint32_t>(
      std::array<std::uint8_t, 4>{colour.r, colour.g, colour.b, 255});
}

ShadedVertex ShadeVertex(const glm::mat4& f, const glm::vec3& position, const ViewportState& vp) {
  return ShadeClipVertex(VertexStage(f, position), vp);
}

ShadedVertex ShadeClipVertex(const glm::vec4& clip, const ViewportState& vp) {
  ShadedVertex s;
  s.v.clip = clip;
  s.v.window = ViewportTransformShader(vp, s.v.clip);  // lavapipe transforms every shader vertex
  s.outcode = Outcode(s.v.clip);
  return s;
}

void AssembleTriangle(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour,
                      const ViewportState& vp, const PixelRect& region,
                      std::vector<TriangleSetup>& out) {
  const unsigned any_outside = v[0]->outcode | v[1]->outcode | v[2]->outcode;
  const unsigned all_outside = v[0]->outcode & v[1]->outcode & v[2]->outcode;
  TriangleSetup setup;
  setup.colour = colour;
  if (any_outside == 0) {
    if (SetUpTriangle(v[0]->v.window, v[1]->v.window, v[2]->v.window, region, setup)) {
      out.push_back(setup);
    }
    return;
  }
  if (all_outside != 0) return;  // entirely outside one plane

  ClippedPolygon polygon;
  ClipTriangle(v[0]->v, v[1]->v, v[2]->v, any_outside, vp, polygon);
  for (int i = 2; i < polygon.count; ++i) {
    const auto& p = polygon.v;
    if (SetUpTriangle(p[0].window, p[static_cast<std::size_t>(i - 1)].window,
                      p[static_cast<std::size_t>(i)].window, region, setup)) {
      out.push_back(setup);
    }
  }
}

std::size_t GeometryScratch::bytes() const {
  std::size_t total = vertices.capacity() * sizeof(ShadedVertex);
  for (const auto& chunk : triangles) total += chunk.capacity() * sizeof(TriangleSetup);
  return total;
}

TriangleChunks ProcessGeometry(const DrawList& list, unsigned threads) {
  GeometryScratch scratch;
  ProcessGeometry(list, threads, scratch);
  return std::move(scratch.triangles);
}

void ProcessGeometry(const DrawList& list, unsigned threads, GeometryScratch& scratch,
                     const std::vector<std::vector<glm::vec4>>* clip) {
  const ViewportState vp = MakeViewport(list.width, list.height);
  const PixelRect region = DrawRegion(vp, list.width, list.height);

  // Global numbering of every draw's vertices and triangles, so both loops split evenly.
  const std::size_t draw_count = list.draws.size();
  std::vector<std::size_t> vertex_start(draw_count + 1, 0), triangle_start(draw_count + 1, 0);
  for (std::size_t d = 0; d < draw_count; ++d) {
    const DrawMesh& mesh = list.meshes[list.draws[d].mesh];
    vertex_start[d + 1] = vertex_start[d] + mesh.positions.size();
    triangle_start[d + 1] = triangle_start[d] + mesh.triangles.size();
  }
  const auto draw_of = [](const std::vector<std::size_t>& start, std::size_t global) {
    return static_cast<std::size_t>(std::upper_bound(start.begin(), start.end(), global) -
                                    start.begin()) -
           1;
  };

  // Threads only pay off for enough work; the result does not depend on their number.
  const auto parts_for = [threads](std::size_t items, std::size_t per_part) {
    return static_cast<unsigned>(std::min<std::size_t>(threads, 1 + items / per_part));
  };

  // Vertex stage (and the shader-side viewport transform and outcodes) for every draw's vertices.
  std::vector<ShadedVertex>& vertices = scratch.vertices;
  vertices.resize(vertex_start[draw_count]);
  ParallelFor(parts_for(vertices.size(), 8192), vertices.size(),
              [&](std::size_t begin, std::size_t end, unsigned) {
                for (std::size_t g = begin; g < end;) {
                  const std::size_t d = draw_of(vertex_start, g);
                  const DrawMesh& mesh = list.meshes[list.draws[d].mesh];
                  const std::size_t stop = std::min(end, vertex_start[d + 1]);
                  for (; g < stop; ++g) {
                    const std::size_t i = g - vertex_start[d];
                    vertices[g] = clip ? ShadeClipVertex((*clip)[d][i], vp)
                                       : ShadeVertex(list.draws[d].F, mesh.positions[i], vp);
                  }
                }
              });

  // Primitive assembly, clipping and setup; each part keeps its slice in order.
  const std::size_t triangle_count = triangle_start[draw_count];
  const unsigned triangle_parts = parts_for(triangle_count, 2048);
  // Reserved here, in the calling thread (a worker's fresh memory would cost a page fault per
  // 4 KiB on every render); with a reused scratch there is usually nothing to allocate.
  TriangleChunks& parts = scratch.triangles;
  parts.resize(triangle_parts);
  for (unsigned part = 0; part < triangle_parts; ++part) {
    parts[part].clear();
    const std::size_t share =
        triangle_count * (part + 1) / triangle_parts - triangle_count * part / triangle_parts;
    parts[part].reserve(share + share / 4 + 16);  // clipping fans may add a few
  }
  ParallelFor(triangle_parts, triangle_count,
              [&](std::size_t begin, std::size_t end, unsigned part) {
                std::vector<TriangleSetup>& out = parts[part];
                for (std::size_t g = begin; g < end;) {
                  const std::size_t d = draw_of(triangle_start, g);
                  const DrawMesh& mesh = list.meshes[list.draws[d].mesh];
                  const ShadedVertex* base = vertices.data() + vertex_start[d];
                  const std::size_t stop = std::min(end, triangle_start[d + 1]);
                  for (; g < stop; ++g) {
                    const std::size_t t = g - triangle_start[d];
                    const auto& tri = mesh.triangles[t];
                    AssembleTriangle({base + tri[0], base + tri[1], base + tri[2]},
                                     PackRgba(mesh.colours[t]), vp, region, out);
                  }
                }
              });
}

}  // namespace twinraster::cpu
