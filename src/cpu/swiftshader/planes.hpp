// SwiftShader's plane set-up (docs/swiftshader-rules.md, "Depth" and "Colour"): the depth plane
// and the perspective-correct colour planes of a primitive, built in float from the snapped
// vertices of the original triangle, never from a clipped polygon, and anchored at its vertex 0
// after a rotation. It does not evaluate them (plane.hpp, cpu/packets.hpp) and draws
// nothing.
#pragma once

#include "cpu/swiftshader/plane.hpp"
#include "cpu/swiftshader/viewport.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstddef>

namespace twinraster::cpu {

// The order set-up reads a triangle's vertices in: rotated so that vertex 0 has the smallest clip
// y, then rotated again so that it has the largest clip w. Rotations keep the winding; they choose
// the anchor, which changes the planes' rounding. order[k] is the input vertex read as vertex k.
std::array<std::size_t, 3> PlaneOrder(const std::array<const SnappedVertex*, 3>& v);

// The depth plane through the three vertices, already in PlaneOrder.
AnchoredPlane TriangleDepthPlane(const SnappedVertex& v0, const SnappedVertex& v1, const SnappedVertex& v2);

// The colour planes of a Gouraud triangle, vertices and their colours already in PlaneOrder: a 3x3
// matrix from the vertices' snapped positions weighted by their clip w turns three values into a
// plane of value/w, and the plane of 1/w.
AnchoredColourPlanes TriangleColourPlanes(const SnappedVertex& v0, const SnappedVertex& v1, const SnappedVertex& v2,
                                          const std::array<glm::vec3, 3>& colours);

// A line's depth plane, from a to b (a first): through a, b and the point a quarter turn from a
// about b, at b's depth, so that depth does not vary across the line.
AnchoredPlane LineDepthPlane(const SnappedVertex& a, const SnappedVertex& b);

}  // namespace twinraster::cpu
