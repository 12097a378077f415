// Stage 2, primitive clipping (Vulkan spec "Primitive Clipping") as lavapipe's draw module does it.
// A depth attachment is always present, so there is no guard band: the view volume is
// -w <= x <= w, -w <= y <= w, 0 <= z <= w.
//  - Each vertex gets an outcode, one bit per plane (bit order below, as the JIT computes them).
//  - No bit in the union: the triangle is drawn as it is. A bit shared by all three: rejected.
//  - Otherwise Sutherland-Hodgman over the planes whose bit is in the union, lowest bit first.
//    A plane's distance is the float dot product of the clip position with the plane vector, summed
//    left to right. A new vertex is interpolated from the edge's endpoint nearer the plane (the
//    inside one on a tie) toward the other: base + t * (other - base), t = |d_base| / |d_out -
//    d_in|. Its window position uses the plain (non-fma) viewport formula. A smooth colour output is
//    interpolated with the same base and t.
//  - The polygon becomes the fan (p0, p[i-1], p[i]), i = 2 .. n-1.
#pragma once

#include "cpu/lavapipe/viewport.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>

namespace twinraster::cpu {

// Outcode bits, in the order the draw module numbers its planes.
enum ClipBits : unsigned {
  kOutsideXMax = 1u << 0,  // x > w
  kOutsideXMin = 1u << 1,  // x + w < 0
  kOutsideYMax = 1u << 2,  // y > w
  kOutsideYMin = 1u << 3,  // y + w < 0
  kOutsideZMin = 1u << 4,  // z < 0
  kOutsideZMax = 1u << 5,  // z > w
};
constexpr int kClipPlaneCount = 6;

// The draw module's buffer size (2 * (6 + 8 user planes) + 1); it gives up on a triangle whose
// polygon would not fit, so the twin does too.
constexpr int kMaxClippedVertices = 2 * (6 + 8) + 1;

unsigned Outcode(const glm::vec4& clip);

// Signed distance of a clip position to plane `plane` (0..5, the bit index above): >= 0 is inside.
float PlaneDistance(const glm::vec4& clip, int plane, bool guard_band_xy = false);

struct ClipVertex {
  glm::vec4 clip{0.0f};
  WindowPos window;  // for shader vertices the fma transform, for new vertices the plain one
  // Whether the polygon edge starting here is drawn in wireframe: true for shader vertices; a
  // vertex made where an edge leaves the volume starts an edge along the clip plane (false), one
  // made where it comes back in copies the flag of the outside vertex it was cut from.
  bool edge = true;
  // A smooth (Gouraud) colour output, interpolated like the position; unused by unlit draws.
  glm::vec3 colour{0.0f};
};

struct ClippedPolygon {
  std::array<ClipVertex, kMaxClippedVertices + 1> v;
  int count = 0;  // < 3: nothing to draw
};

// The new vertex where edge prev -> cur crosses a plane; d_prev and d_cur are their distances and
// have different signs (d >= 0 counts as inside).
ClipVertex IntersectEdge(const ClipVertex& prev, float d_prev, const ClipVertex& cur, float d_cur,
                         const ViewportState& vp);

// Clips triangle (a, b, c) against the planes in `clipmask` (the union of the vertices' outcodes,
// not 0, and the intersection 0). A NaN or infinite distance drops the whole triangle.
// `guard_band_xy`: the x and y planes are the guard band's |x|, |y| <= 2w (the outcodes still say
// which planes to clip against: lavapipe's JIT computes them against w whatever the planes).
void ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, unsigned clipmask,
                  const ViewportState& vp, ClippedPolygon& out, bool guard_band_xy = false);

}  // namespace twinraster::cpu
