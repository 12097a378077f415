// Primitive assembly as lavapipe does it, from shaded vertices to TriangleSetups or, in polygon
// mode LINE, LineSetups: a triangle is drawn whole when no vertex is outside, dropped when all are
// outside one plane, and clipped into a fan otherwise (clipping.hpp), each triangle of the fan set
// up on its own (setup.hpp). LavapipeAssembly is what the shared loop (cpu/chunk_assembly.hpp)
// calls, LavapipeScratch what it fills and the renderer draws. It does not rasterize
// (coverage.hpp) and does not follow SwiftShader's assembly (cpu/swiftshader/assembly.hpp).
#pragma once

#include "cpu/lavapipe/clipping.hpp"
#include "cpu/lavapipe/coverage.hpp"
#include "cpu/lavapipe/line_setup.hpp"
#include "cpu/lavapipe/planes.hpp"
#include "cpu/lavapipe/setup.hpp"
#include "cpu/lavapipe/viewport.hpp"
#include "cpu/packets.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// A vertex after the vertex stage: clip position, fma window position, outcode.
struct ShadedVertex {
  ClipVertex v;
  unsigned outcode = 0;
};
ShadedVertex ShadeVertex(const glm::mat4& f, const glm::vec3& position, const ViewportState& vp);
ShadedVertex ShadeClipVertex(const glm::vec4& clip, const ViewportState& vp);  // vertex stage already done

// One input triangle: trivially accepted, rejected, or clipped into a fan; appends what it draws.
void AssembleTriangle(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour, const ViewportState& vp,
                      const PixelRect& region, std::vector<TriangleSetup>& out);

// The same for a Gouraud triangle whose corners have the given colours: each triangle it draws
// gets its ColourPlanes appended to `planes`, and their index as its colour.
void AssembleSmoothTriangle(const std::array<const ShadedVertex*, 3>& v, const std::array<glm::vec3, 3>& colours,
                            const ViewportState& vp, const PixelRect& region, std::vector<TriangleSetup>& out,
                            std::vector<ColourPlanes>& planes);

// A wireframe triangle: its edges as lavapipe's draw module emits them for polygonMode LINE, each
// set up as a line and appended. Unclipped: v2→v0, v0→v1, v1→v2, whatever the winding, even at
// zero area. Clipped into p0..p(n-1): p0→p1, …, p(n-3)→p(n-2), then p(n-1)→p0, then
// p(n-2)→p(n-1) (for n = 3 the unclipped order), leaving out the edges along a clip plane. Where
// the rules say so (Mesa 25), x and y are clipped at the guard band instead (ClipTriangle).
void AssembleWireframe(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour, const ViewportState& vp,
                       const PixelRect& region, std::vector<LineSetup>& out);

// The triangles in draw order, as consecutive parts (one per setup thread: no merge copy).
using TriangleChunks = std::vector<std::vector<TriangleSetup>>;
using LineChunks = std::vector<std::vector<LineSetup>>;  // the same for a wireframe's lines

// The rows of one primitive that lie in [row_begin, row_end): on_span(py, span) for each covered
// span, top down. `part` is unused: lavapipe's primitives carry everything they need.
struct TriangleRows {
  template <class OnSpan>
  void operator()(std::size_t, const TriangleSetup& t, int row_begin, int row_end, OnSpan&& on_span) const {
    RasterizeRows(t, row_begin, row_end, [&](const TriangleSetup&, int py, Span span) { on_span(py, span); });
  }
};
struct LineRows {
  template <class OnSpan>
  void operator()(std::size_t, const LineSetup& line, int row_begin, int row_end, OnSpan&& on_span) const {
    for (int py = row_begin; py < row_end; ++py) {
      const Span span = CoveredSpan(line.edges.data(), line.edges.size(), line.bounds, py);
      if (span.begin < span.end) on_span(py, span);
    }
  }
};

// What lavapipe's assembly sets a chunk up into, per part (one per setup thread), kept from one
// chunk and one render to the next: fresh memory costs a page fault per 4 KiB.
struct LavapipeScratch {
  bool wireframe = false;  // the chunk's primitives are lines, not triangles
  std::vector<ShadedVertex> vertices;
  TriangleChunks triangles;
  std::vector<std::vector<ColourPlanes>> colour_planes;  // per part: its smooth triangles' planes
  LineChunks lines;

  // Empties the parts and reserves room for `share(part)` input triangles in each.
  template <class Share>
  void Reserve(unsigned parts, bool wireframe_list, Share&& share);
  // Bins part p's primitives into bins[band] (the indices of those whose box touches the band).
  void Bin(unsigned part, std::vector<std::vector<std::uint32_t>>& bins) const {
    if (wireframe)
      BinPrimitives(lines[part], bins);
    else
      BinPrimitives(triangles[part], bins);
  }
  // draw(parts, rows) with this chunk's primitives and how to cover their rows.
  template <class DrawFn>
  void Draw(int /*width*/, DrawFn&& draw) const {
    if (wireframe)
      draw(lines, LineRows{});
    else
      draw(triangles, TriangleRows{});
  }
  // The colour planes of part p's smooth triangle whose colour is `index`.
  const ColourPlanes& SmoothPlanes(std::size_t part, std::uint32_t index) const { return colour_planes[part][index]; }
  std::size_t bytes() const;
};

template <class Share>
void LavapipeScratch::Reserve(unsigned parts, bool wireframe_list, Share&& share) {
  wireframe = wireframe_list;
  const auto fit = [&](auto& per_part, bool used) {
    per_part.resize(used ? parts : 0);
    for (auto& part : per_part) part.clear();
  };
  fit(triangles, !wireframe);
  fit(colour_planes, !wireframe);
  fit(lines, wireframe);
  for (unsigned part = 0; part < parts; ++part) {
    const std::size_t n = share(part);
    if (wireframe)
      lines[part].reserve(3 * n + 16);
    else
      triangles[part].reserve(n + n / 4 + 16);  // fans add a few
  }
}

// Lavapipe's primitive assembly and set-up (the Assemble functions above), as the shared loop
// calls it: per vertex a window position, per triangle a fan of TriangleSetups or three lines.
class LavapipeAssembly {
 public:
  using Vertex = ShadedVertex;
  using Scratch = LavapipeScratch;

  LavapipeAssembly(std::uint32_t width, std::uint32_t height, const RasterRules& rules, LavapipeScratch& scratch)
      : vp_(MakeViewport(width, height, rules)), region_(DrawRegion(vp_, width, height)), scratch_(scratch) {}

  Vertex Shade(const glm::vec4& clip) const { return ShadeClipVertex(clip, vp_); }
  void Flat(const std::array<const Vertex*, 3>& v, std::uint32_t colour, unsigned part) const {
    AssembleTriangle(v, colour, vp_, region_, scratch_.triangles[part]);
  }
  void Smooth(const std::array<const Vertex*, 3>& v, const std::array<glm::vec3, 3>& colours, unsigned part) const {
    AssembleSmoothTriangle(v, colours, vp_, region_, scratch_.triangles[part], scratch_.colour_planes[part]);
  }
  void Wireframe(const std::array<const Vertex*, 3>& v, std::uint32_t colour, unsigned part) const {
    AssembleWireframe(v, colour, vp_, region_, scratch_.lines[part]);
  }

 private:
  ViewportState vp_;
  PixelRect region_;
  LavapipeScratch& scratch_;
};

}  // namespace twinraster::cpu
