// The draw list's geometry with error bounds: each triangle clipped by the view volume in double, as
// the truth clips, and mapped to the framebuffer, every vertex carrying how far a conformant
// implementation's vertex may lie from it (float vertex shading, clipping and the viewport
// transform in float, snapping to subPixelPrecisionBits).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::verify {

// A clip-space vertex: the truth's position, a bound on |implementation - truth| per component,
// a lit colour (0..1) carried through clipping, and the clip planes it was made on (a bit each).
struct BoundedVertex {
  glm::dvec4 clip{0.0};
  glm::dvec4 error{0.0};
  glm::dvec3 colour{0.0};
  unsigned planes = 0;
};

// Clip positions of a mesh's vertices as the device was given them: the draw list's float F times
// its float positions, evaluated exactly (in double), with the error of a vertex shader computing
// the same product in float (each operation correctly rounded, as the spec requires of OpFMul,
// OpFAdd and OpFma). The host's rounding of F to float is not the device's to answer for: every
// implementation gets the same F (bench measures that rounding against the truth).
// Into `out`, whose storage is reused from draw to draw.
void BoundVertices(const glm::mat4& float_f, const std::vector<glm::vec3>& float_positions,
                   std::vector<BoundedVertex>& out);

// A framebuffer vertex: x and y in pixels, z the depth; xy_error bounds the distance along x and
// along y (snapping included), z_error the depth's.
struct WindowVertex {
  glm::dvec2 xy{0.0};
  double z = 0;
  double xy_error = 0, z_error = 0;
  glm::dvec3 colour{0.0};
  double w = 1;  // clip w, for perspective-correct colour
};

// A triangle clipped (at most 9 vertices, a convex fan), in the framebuffer. edge_from_clipping[i]
// is true for the edge v[i] -> v[i + 1] made by clipping (it lies on a plane).
struct WindowPolygon {
  std::array<WindowVertex, 9> v;
  std::array<bool, 9> edge_from_clipping{};
  std::size_t size = 0;
};

// The viewport transform of one vertex inside the view volume (W x H, depth range [0, 1]).
WindowVertex MapToWindow(const BoundedVertex& v, std::uint32_t width, std::uint32_t height, int subpixel_bits);
bool InsideViewVolume(const BoundedVertex& v);  // no clip plane cuts it off (finite too)

// Which planes ClipToWindow cuts by. kView: -w <= x, y <= w, 0 <= z <= w, as the truth does.
// kDepth: 0 <= z <= w only, for lines: an implementation may clip a line at the viewport, at a
// guard band or not at all (Primitive Clipping: a line "may be clipped"), so a wireframe edge is
// kept whole across the canvas's border and the border is only where its pixels end.
enum class ClipVolume { kView, kDepth };

// Clips (a, b, c) by `volume`'s planes, widening each new vertex's bound by the float arithmetic
// of finding it, then maps every vertex to the W x H framebuffer. An empty polygon: nothing
// inside, or not finite.
WindowPolygon ClipToWindow(const BoundedVertex& a, const BoundedVertex& b, const BoundedVertex& c, std::uint32_t width,
                           std::uint32_t height, int subpixel_bits, ClipVolume volume = ClipVolume::kView);

}  // namespace twinraster::verify
