// Set-up as SwiftShader does it (docs/swiftshader-rules.md, "Triangle setup and coverage"): what
// one primitive carries to the rasterizer (its outline's points, its winding, its box and its
// depth plane), the box the outline can cover, and the winding from the float area of the snapped
// vertices. It does not scan-convert the outline (coverage.hpp) and does not build the planes
// (planes.hpp); lavapipe's set-up is cpu/lavapipe/setup.hpp.
#pragma once

#include "cpu/packets.hpp"
#include "cpu/swiftshader/plane.hpp"
#include "cpu/swiftshader/viewport.hpp"

#include <cstdint>

namespace twinraster::cpu {

// One primitive for SwiftShader's rules: a triangle or a clipped polygon of one, or a wireframe
// line's clipped quad. Its points live in a pool beside it (SwiftShaderScratch::outline_points).
struct OutlineSetup {
  std::uint32_t first = 0;  // its points are the pool's [first, first + count)
  std::uint8_t count = 0;
  bool d = true;        // the winding: edges run p[i] -> p[i+1] when true, p[i+1] -> p[i] when false
  bool smooth = false;  // Gouraud: `colour` is the index of its AnchoredColourPlanes
  PixelRect bounds;     // pixels that may be covered, inside the framebuffer
  AnchoredPlane depth;
  std::uint32_t colour = 0;  // RGBA8, or the index of its colour planes
};

// The rows and columns the polygon's outline can cover, clamped to the framebuffer. False when it
// covers no row.
bool OutlineBounds(const SnappedPoint* points, int count, int width, int height, PixelRect& bounds);

// SwiftShader's winding for the triangle of shader vertices a, b, c: the float area of their
// snapped positions, negated when an odd number of them have a negative w (-0 counts), is > 0.
bool OutlineWinding(const SnappedVertex& a, const SnappedVertex& b, const SnappedVertex& c);

}  // namespace twinraster::cpu
