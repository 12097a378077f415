// Stages 1 to 5 for a whole draw list, done once before rasterization: vertex stage, clipping,
// viewport transform and triangle setup. The result lists the triangles in the order lavapipe
// rasterizes them: draws in list order, triangles in index order, a clipped triangle's fan in
// fan order. Parallel over vertices and over triangles; the result stays in ordered chunks.
#pragma once

#include "cpu/clipping.hpp"
#include "cpu/triangle_setup.hpp"
#include "cpu/viewport_transform.hpp"
#include "chain/draw_list.hpp"

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
void AssembleTriangle(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour,
                      const ViewportState& vp, const PixelRect& region,
                      std::vector<TriangleSetup>& out);

// The triangles in draw order, as consecutive chunks (one per setup thread: no merge copy).
using TriangleChunks = std::vector<std::vector<TriangleSetup>>;

TriangleChunks ProcessGeometry(const DrawList& list, unsigned threads);

// The same, with memory that can be kept from one render to the next: fresh memory costs a page
// fault per 4 KiB, which for small scenes is much of the work. The result is scratch.triangles.
struct GeometryScratch {
  std::vector<ShadedVertex> vertices;
  TriangleChunks triangles;
  std::size_t bytes() const;
};
// `clip`: when given, the positions another vertex stage computed (one vector per draw) replace
// this one's F · (p, 1).
void ProcessGeometry(const DrawList& list, unsigned threads, GeometryScratch& scratch,
                     const std::vector<std::vector<glm::vec4>>* clip = nullptr);

}  // namespace twinraster::cpu
