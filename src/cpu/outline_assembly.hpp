// Primitive assembly as SwiftShader does it, from shaded vertices to OutlineSetups
// (docs/swiftshader-rules.md): a triangle is dropped when a coordinate is not finite or all three
// vertices are outside one plane, clipped when any is outside, and set up as one polygon with the
// original triangle's planes. In polygon mode LINE each triangle gives three lines, v0 -> v1,
// v1 -> v2, v2 -> v0, each a 1-pixel-wide quad built in clip space, clipped and set up alone; the
// triangle itself is never clipped. It does not rasterize (outline.hpp) and does not follow
// lavapipe's assembly (geometry.hpp).
#pragma once

#include "cpu/colour_planes.hpp"
#include "cpu/outline.hpp"
#include "cpu/snapped_vertex.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// Where assembly appends: the set-ups, their points, and the colour planes of smooth ones.
struct OutlineOutput {
  std::vector<OutlineSetup>& setups;
  std::vector<SnappedPoint>& points;
  std::vector<AnchoredColourPlanes>& planes;
};

using OutlineTriangle = std::array<const SnappedVertex*, 3>;

// A filled triangle of one colour (unlit, or flat: the lit colour of its first vertex).
void AssembleOutlineTriangle(const OutlineTriangle& v, std::uint32_t colour, const SnapViewport& vp, OutlineOutput out);

// A Gouraud triangle whose vertices have the given colours.
void AssembleOutlineSmooth(const OutlineTriangle& v, const std::array<glm::vec3, 3>& colours, const SnapViewport& vp,
                           OutlineOutput out);

// A wireframe triangle's three lines.
void AssembleOutlineWireframe(const OutlineTriangle& v, std::uint32_t colour, const SnapViewport& vp,
                              OutlineOutput out);

}  // namespace twinraster::cpu
