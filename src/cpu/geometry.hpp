// Stages 1 to 5 for a whole draw list, done once before rasterization: vertex stage, clipping,
// viewport transform and triangle setup. The result lists the triangles in the order lavapipe
// rasterizes them: draws in list order, triangles in index order, a clipped triangle's fan in
// fan order. Parallel over vertices and over triangles, with an order-preserving merge.
#pragma once

#include "cpu/clipping.hpp"
#include "cpu/triangle_setup.hpp"
#include "cpu/viewport_transform.hpp"
#include "draw_list.hpp"

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

constexpr std::uint32_t kMaxFramebufferSize = 16384;  // lavapipe's maxViewportDimensions

// Throws std::invalid_argument: size 0 or over the limit, mesh or vertex index out of range, a
// triangle without colour.
void ValidateDrawList(const DrawList& list);

// Rgb8 as the RGBA8 bytes (r, g, b, 255) in memory, viewed as one 32-bit word.
std::uint32_t PackRgba(Rgb8 colour);

// A vertex after the vertex stage: clip position, fma window position, outcode.
struct ShadedVertex {
  ClipVertex v;
  unsigned outcode = 0;
};
ShadedVertex ShadeVertex(const glm::mat4& f, const glm::vec3& position, const ViewportState& vp);

// One input triangle: trivially accepted, rejected, or clipped into a fan; appends what it draws.
void AssembleTriangle(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour,
                      const ViewportState& vp, const PixelRect& region,
                      std::vector<TriangleSetup>& out);

std::vector<TriangleSetup> ProcessGeometry(const DrawList& list, unsigned threads);

}  // namespace twinraster::cpu
