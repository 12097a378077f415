// Stage 2 as SwiftShader clips (Vulkan spec "Primitive Clipping"; docs/swiftshader-rules.md,
// "Clipping"): a polygon in clip space against the view volume's planes, in the order near, far,
// left, right, top, bottom, each only if some vertex is outside it. No guard band. Only positions
// are clipped: depth and colour come from the original triangle's planes (plane.hpp),
// and the polygon only bounds coverage (coverage.hpp). It does not snap the new vertices
// (viewport.hpp) and is not lavapipe's clipper (cpu/lavapipe/clipping.hpp).
#pragma once

#include <glm/vec4.hpp>

#include <array>

namespace twinraster::cpu {

// SwiftShader's polygon buffer holds 16; a triangle clipped by six planes has at most 9 vertices,
// a wireframe line's quad at most 10.
constexpr int kMaxOutlinePoints = 16;

struct ClipSpacePolygon {
  std::array<glm::vec4, kMaxOutlinePoints> v{};
  int count = 0;
};

// Sutherland-Hodgman over the planes whose SnapClipBits are in `planes`, stopping once fewer than
// three vertices remain. For edge i -> j with distances di, dj: Vi is kept if di >= 0, and a new
// vertex ((dj Vi - di Vj) * (1 / (dj - di))) is made, from the inside end, where the edge crosses.
// False when fewer than three vertices remain.
bool ClipPolygon(ClipSpacePolygon& polygon, unsigned planes);

}  // namespace twinraster::cpu
