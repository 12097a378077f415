#include "cpu/geometry.hpp"

#include "cpu/denormals.hpp"
#include "cpu/lighting.hpp"
#include "cpu/parallel.hpp"
#include "cpu/rasterize.hpp"
#include "cpu/vertex_stage.hpp"

#include <algorithm>
#include <bit>
#include <stdexcept>
#include <string>

namespace twinraster::cpu {

std::uint32_t PackRgba(Rgb8 colour) {
  return std::bit_cast<std::uint32_t>(std::array<std::uint8_t, 4>{colour.r, colour.g, colour.b, 255});
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

namespace {

// Primitive assembly and clipping for one triangle: set_up(a, b, c) for the triangle itself, or
// for each triangle of its clipped fan, or for none.
template <class SetUp>
void AssembleFan(const ClipVertex& a, unsigned a_out, const ClipVertex& b, unsigned b_out, const ClipVertex& c,
                 unsigned c_out, const ViewportState& vp, SetUp&& set_up) {
  const unsigned any_outside = a_out | b_out | c_out;
  if (any_outside == 0) {
    set_up(a, b, c);
    return;
  }
  if ((a_out & b_out & c_out) != 0) return;  // entirely outside one plane

  ClippedPolygon polygon;
  ClipTriangle(a, b, c, any_outside, vp, polygon);
  for (int i = 2; i < polygon.count; ++i) {
    const auto& p = polygon.v;
    set_up(p[0], p[static_cast<std::size_t>(i - 1)], p[static_cast<std::size_t>(i)]);
  }
}

}  // namespace

void AssembleTriangle(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour, const ViewportState& vp,
                      const PixelRect& region, std::vector<TriangleSetup>& out) {
  // Set up in place: a copy through the stack would cost store-forwarding stalls on every field.
  AssembleFan(v[0]->v, v[0]->outcode, v[1]->v, v[1]->outcode, v[2]->v, v[2]->outcode, vp,
              [&](const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
                TriangleSetup& setup = out.emplace_back();
                setup.colour = colour;
                if (!SetUpTriangle(a.window, b.window, c.window, region, setup, vp.rules))
                  out.pop_back();
                else
                  setup.depth.fused = vp.rules.fused_multiply_add;
              });
}

void AssembleSmoothTriangle(const std::array<const ShadedVertex*, 3>& v, const std::array<glm::vec3, 3>& colours,
                            const ViewportState& vp, const PixelRect& region, std::vector<TriangleSetup>& out,
                            std::vector<ColourPlanes>& planes) {
  std::array<ClipVertex, 3> corner = {v[0]->v, v[1]->v, v[2]->v};
  for (std::size_t k = 0; k < 3; ++k) corner[k].colour = colours[k];
  AssembleFan(corner[0], v[0]->outcode, corner[1], v[1]->outcode, corner[2], v[2]->outcode, vp,
              [&](const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
                TriangleSetup& setup = out.emplace_back();
                if (!SetUpTriangle(a.window, b.window, c.window, region, setup, vp.rules)) {
                  out.pop_back();
                  return;
                }
                setup.smooth = true;
                setup.depth.fused = vp.rules.fused_multiply_add;
                setup.colour = static_cast<std::uint32_t>(planes.size());
                // In post-swap order, like the depth plane.
                const bool fused = vp.rules.fused_multiply_add;
                planes.push_back(setup.swapped ? MakeColourPlanes(a, c, b, fused) : MakeColourPlanes(a, b, c, fused));
              });
}

void AssembleWireframe(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour, const ViewportState& vp,
                       const PixelRect& region, std::vector<LineSetup>& out) {
  const auto line = [&](const WindowPos& a, const WindowPos& b) {
    LineSetup& setup = out.emplace_back();
    setup.colour = colour;
    if (!SetUpLine(a, b, region, vp.rules, setup)) out.pop_back();
  };
  const unsigned any_outside = v[0]->outcode | v[1]->outcode | v[2]->outcode;
  const unsigned all_outside = v[0]->outcode & v[1]->outcode & v[2]->outcode;
  if (any_outside == 0) {
    line(v[2]->v.window, v[0]->v.window);
    line(v[0]->v.window, v[1]->v.window);
    line(v[1]->v.window, v[2]->v.window);
    return;
  }
  if (all_outside != 0) return;

  ClippedPolygon polygon;
  ClipTriangle(v[0]->v, v[1]->v, v[2]->v, any_outside, vp, polygon, vp.rules.wireframe_guard_band);
  const int n = polygon.count;
  const auto edge = [&](int i, int j) {
    const ClipVertex& from = polygon.v[static_cast<std::size_t>(i)];
    if (from.edge) line(from.window, polygon.v[static_cast<std::size_t>(j)].window);
  };
  if (n < 3) return;
  if (n == 3) {
    edge(2, 0);
    edge(0, 1);
    edge(1, 2);
    return;
  }
  for (int i = 0; i + 2 < n; ++i) edge(i, i + 1);
  edge(n - 1, 0);
  edge(n - 2, n - 1);
}

std::size_t GeometryScratch::bytes() const {
  std::size_t total = vertices.capacity() * sizeof(ShadedVertex) + vertex_start.capacity() * sizeof(std::size_t);
  for (const auto& part : triangles) total += part.capacity() * sizeof(TriangleSetup);
  for (const auto& part : colour_planes) total += part.capacity() * sizeof(ColourPlanes);
  for (const auto& part : lines) total += part.capacity() * sizeof(LineSetup);
  total += snapped.capacity() * sizeof(SnappedVertex);
  for (const auto& part : outlines) total += part.capacity() * sizeof(OutlineSetup);
  for (const auto& part : outline_points) total += part.capacity() * sizeof(SnappedPoint);
  for (const auto& part : outline_planes) total += part.capacity() * sizeof(AnchoredColourPlanes);
  for (const auto& part : bins)
    for (const auto& bin : part) total += bin.capacity() * sizeof(std::uint32_t);
  return total;
}

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
  GeometryScratch scratch;
  ProcessGeometry(list, GeometryChunk{.draw_begin = 0, .draw_end = list.draws.size()}, threads, rules, scratch);
  return std::move(scratch.triangles);
}

namespace {

// Threads only pay off for enough work; the result does not depend on their number.
unsigned PartsFor(unsigned threads, std::size_t items, std::size_t per_part) {
  return static_cast<unsigned>(std::min<std::size_t>(threads, 1 + items / per_part));
}

// The draw i with start[i] <= global < start[i + 1].
std::size_t DrawOf(const std::vector<std::size_t>& start, std::size_t global) {
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

// Lavapipe's primitive assembly and set-up (the Assemble functions above), as the shared loop
// calls it: per vertex a window position, per triangle a fan of TriangleSetups or three lines.
struct LavapipeAssembly {
  using Vertex = ShadedVertex;
  ViewportState vp;
  PixelRect region;
  GeometryScratch& scratch;

  static std::vector<Vertex>& Vertices(GeometryScratch& s) { return s.vertices; }
  Vertex Shade(const glm::vec4& clip) const { return ShadeClipVertex(clip, vp); }
  void Flat(const std::array<const Vertex*, 3>& v, std::uint32_t colour, unsigned part) const {
    AssembleTriangle(v, colour, vp, region, scratch.triangles[part]);
  }
  void Smooth(const std::array<const Vertex*, 3>& v, const std::array<glm::vec3, 3>& colours, unsigned part) const {
    AssembleSmoothTriangle(v, colours, vp, region, scratch.triangles[part], scratch.colour_planes[part]);
  }
  void Wireframe(const std::array<const Vertex*, 3>& v, std::uint32_t colour, unsigned part) const {
    AssembleWireframe(v, colour, vp, region, scratch.lines[part]);
  }
};

// SwiftShader's (outline_assembly.hpp): per vertex a snapped position, per triangle one polygon,
// or three lines, each an OutlineSetup.
struct SwiftShaderAssembly {
  using Vertex = SnappedVertex;
  SnapViewport vp;
  GeometryScratch& scratch;

  static std::vector<Vertex>& Vertices(GeometryScratch& s) { return s.snapped; }
  Vertex Shade(const glm::vec4& clip) const { return SnapShaderVertex(clip, vp); }
  OutlineOutput Out(unsigned part) const {
    return {scratch.outlines[part], scratch.outline_points[part], scratch.outline_planes[part]};
  }
  void Flat(const OutlineTriangle& v, std::uint32_t colour, unsigned part) const {
    AssembleOutlineTriangle(v, colour, vp, Out(part));
  }
  void Smooth(const OutlineTriangle& v, const std::array<glm::vec3, 3>& colours, unsigned part) const {
    AssembleOutlineSmooth(v, colours, vp, Out(part));
  }
  void Wireframe(const OutlineTriangle& v, std::uint32_t colour, unsigned part) const {
    AssembleOutlineWireframe(v, colour, vp, Out(part));
  }
};

// Vertex stage (and the device's viewport transform and outcodes) for every draw's vertices, into
// the assembly's vertices from scratch.vertex_start[i] for draw i.
template <class Assembly>
void ShadeVertices(const ChunkDraws& draws, const Assembly& assembly, const std::vector<std::vector<glm::vec4>>* clip,
                   unsigned threads, bool flush_denormals, GeometryScratch& scratch) {
  const DrawList& list = draws.list;
  const std::size_t draw_begin = draws.chunk.draw_begin;
  auto& vertices = Assembly::Vertices(scratch);
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
void ReserveParts(std::size_t triangle_count, unsigned parts, unsigned band_count, PrimitiveKind kind,
                  GeometryScratch& scratch) {
  const auto fit = [&](auto& per_part, bool used) {
    per_part.resize(used ? parts : 0);
    for (auto& part : per_part) part.clear();
  };
  scratch.kind = kind;
  fit(scratch.triangles, kind == PrimitiveKind::kTriangles);
  fit(scratch.colour_planes, kind == PrimitiveKind::kTriangles);
  fit(scratch.lines, kind == PrimitiveKind::kLines);
  fit(scratch.outlines, kind == PrimitiveKind::kOutlines);
  fit(scratch.outline_points, kind == PrimitiveKind::kOutlines);
  fit(scratch.outline_planes, kind == PrimitiveKind::kOutlines);
  scratch.bins.resize(parts);
  for (unsigned part = 0; part < parts; ++part) {
    scratch.bins[part].resize(band_count);
    for (auto& bin : scratch.bins[part]) bin.clear();
    const std::size_t share = triangle_count * (part + 1) / parts - triangle_count * part / parts;
    switch (kind) {
      case PrimitiveKind::kTriangles: scratch.triangles[part].reserve(share + share / 4 + 16); break;  // fans add a few
      case PrimitiveKind::kLines: scratch.lines[part].reserve(3 * share + 16); break;
      case PrimitiveKind::kOutlines:
        scratch.outlines[part].reserve(share + 16);
        scratch.outline_points[part].reserve(3 * share + 16);
        break;
    }
  }
}

// Bins one part's primitives while they are still in cache (most touch one band).
template <class Primitives>
void Bin(const Primitives& primitives, std::vector<std::vector<std::uint32_t>>& bins) {
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    for (int band = FirstBand(primitives[i].bounds); band <= LastBand(primitives[i].bounds); ++band) {
      bins[static_cast<std::size_t>(band)].push_back(static_cast<std::uint32_t>(i));
    }
  }
}

void BinPart(GeometryScratch& scratch, unsigned part) {
  switch (scratch.kind) {
    case PrimitiveKind::kTriangles: Bin(scratch.triangles[part], scratch.bins[part]); break;
    case PrimitiveKind::kLines: Bin(scratch.lines[part], scratch.bins[part]); break;
    case PrimitiveKind::kOutlines: Bin(scratch.outlines[part], scratch.bins[part]); break;
  }
}

// The shared loop: a later slice of one draw reuses the vertices its first slice shaded, and each
// part of the triangles keeps its slice in order. The per-triangle loop is kept whole here: it is
// the hot one, and GCC compiles it to fewer instructions than when it is split into functions.
template <class Assembly>
void AssembleChunk(const ChunkDraws& draws, const Assembly& assembly, const std::vector<std::vector<glm::vec4>>* clip,
                   unsigned threads, const RasterRules& rules, unsigned band_count, GeometryScratch& scratch) {
  const DrawList& list = draws.list;
  const GeometryChunk& chunk = draws.chunk;
  if (chunk.shade_vertices) ShadeVertices(draws, assembly, clip, threads, rules.flush_denormals, scratch);

  const std::vector<std::size_t>& triangle_start = draws.triangle_start;
  const std::size_t first_triangle = draws.first_triangle;
  const std::size_t triangle_count = triangle_start[draws.count];
  const unsigned triangle_parts = PartsFor(threads, triangle_count, 2048);
  const bool wireframe = list.wireframe;
  const bool outlines = rules.rasterizer == Rasterizer::kSwiftShader;
  ReserveParts(triangle_count, triangle_parts, band_count,
               outlines    ? PrimitiveKind::kOutlines
               : wireframe ? PrimitiveKind::kLines
                           : PrimitiveKind::kTriangles,
               scratch);
  const auto& vertices = Assembly::Vertices(scratch);
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
    if (band_count != 0) BinPart(scratch, part);
  });
}

}  // namespace

void ProcessGeometry(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                     GeometryScratch& scratch, const std::vector<std::vector<glm::vec4>>* clip, unsigned band_count) {
  const ChunkDraws draws(list, chunk);
  if (rules.rasterizer == Rasterizer::kSwiftShader) {
    const SwiftShaderAssembly assembly{MakeSnapViewport(list.width, list.height), scratch};
    AssembleChunk(draws, assembly, clip, threads, rules, band_count, scratch);
    return;
  }
  const ViewportState vp = MakeViewport(list.width, list.height, rules);
  const LavapipeAssembly assembly{vp, DrawRegion(vp, list.width, list.height), scratch};
  AssembleChunk(draws, assembly, clip, threads, rules, band_count, scratch);
}

}  // namespace twinraster::cpu
