// Stages 1 to 5, vertex stage, clipping, viewport transform and triangle setup, for one chunk of
// a draw list at a time, so that memory stays bounded however large the scene. The result lists
// the chunk's primitives in the order the device rasterizes them: draws in list order, triangles
// in index order, a clipped triangle's fan in fan order (lavapipe), or its one polygon
// (SwiftShader, outline_assembly.hpp). Parallel over vertices and over triangles; the result
// stays in ordered parts. The loop is one for both devices: the rules choose only the assembly
// it calls.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/clipping.hpp"
#include "cpu/colour_planes.hpp"
#include "cpu/line_setup.hpp"
#include "cpu/outline_assembly.hpp"
#include "cpu/triangle_setup.hpp"
#include "cpu/viewport_transform.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// Rgb8 as the RGBA8 bytes (r, g, b, 255) in memory, viewed as one 32-bit word.
std::uint32_t PackRgba(Rgb8 colour);

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

// What a chunk was set up into: lavapipe's triangles or lines, or SwiftShader's outlines.
enum class PrimitiveKind : std::uint8_t { kTriangles, kLines, kOutlines };

// Memory kept from one chunk, and one render, to the next: fresh memory costs a page fault per
// 4 KiB, which for small scenes is much of the work.
struct GeometryScratch {
  PrimitiveKind kind = PrimitiveKind::kTriangles;
  std::vector<ShadedVertex> vertices;                    // lavapipe's
  std::vector<SnappedVertex> snapped;                    // SwiftShader's
  std::vector<std::size_t> vertex_start;                 // per draw of the shaded chunk, into the vertices
  TriangleChunks triangles;                              // the result
  std::vector<std::vector<ColourPlanes>> colour_planes;  // per part: its smooth triangles' planes
  LineChunks lines;                                      // the result, for a wireframe draw list
  // The result for SwiftShader's rules, filled or wireframe, per part: the set-ups, their points
  // and the colour planes of the smooth ones.
  std::vector<std::vector<OutlineSetup>> outlines;
  std::vector<std::vector<SnappedPoint>> outline_points;
  std::vector<std::vector<AnchoredColourPlanes>> outline_planes;
  // bins[p][b]: indices into the primitives of part p (triangles[p], lines[p] or outlines[p]) of
  // those whose box touches band b (kBandRows rows), in order; binned as they are set up, while
  // still in cache, so that each band's rasterizer reads only the primitives it draws.
  std::vector<std::vector<std::vector<std::uint32_t>>> bins;
  std::size_t bytes() const;
};

// Sets up one chunk into the scratch (triangles or lines by lavapipe's rules, outlines by
// SwiftShader's), and, when band_count > 0, bins them into scratch.bins. `clip`: when given, the
// positions another vertex stage computed (one vector per draw) replace this one's F · (p, 1).
// `rules`: the device whose arithmetic to follow.
void ProcessGeometry(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                     GeometryScratch& scratch, const std::vector<std::vector<glm::vec4>>* clip = nullptr,
                     unsigned band_count = 0);

// The whole list as one chunk, for tests that want every triangle at once (lavapipe's rules: the
// triangles of SwiftShader's are outlines).
TriangleChunks ProcessGeometry(const DrawList& list, unsigned threads, const RasterRules& rules = {});

}  // namespace twinraster::cpu
