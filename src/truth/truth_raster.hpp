// The truth's per-triangle stages after the viewport transform: coverage at pixel centres with
// exact edge-function signs and the twin's top-left rule, depth interpolated in double, and the
// fragment operations (depth test, depth write, colour write: flat, or lit and interpolated).
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace twinraster::truth {

// Framebuffer positions (x, y, depth) of one triangle, and its flat colour; or, lit, each
// corner's colour (0..1) with its clip w, interpolated perspective-correctly (a flat-lit triangle
// gives all three corners the same colour).
struct WindowTriangle {
  std::array<glm::dvec3, 3> v;
  Rgb8 colour;
  std::optional<std::array<glm::dvec3, 3>> colours;
  std::array<double, 3> w{1.0, 1.0, 1.0};
  std::uint64_t surface = 0;  // which surface this is, for TruthTarget::surfaces (not 0)
};

// Colour and a double depth buffer, cleared for the list's depth mode (standard or reversed Z).
struct TruthTarget {
  Image colour;
  std::vector<double> depth;
  bool reversed_z = false;  // clear 0, GREATER; otherwise clear 1, LESS
  // Per pixel, the WindowTriangle::surface that wrote it (0: background); empty unless asked for.
  std::vector<std::uint64_t> surfaces;

  TruthTarget(std::uint32_t width, std::uint32_t height, Rgb8 background, bool reversed, bool keep_surfaces = false);
  std::size_t index(int px, int py) const { return std::size_t(py) * colour.width + std::size_t(px); }
};

// Whether an edge function that is exactly 0 at a centre counts as inside: for a left edge
// (a.y < b.y) or a top edge (a.y == b.y, a.x > b.x) of a triangle with positive area, exactly as
// the twin's MakeEdge decides from dcdx = Yi - Yj and dcdy = Xi - Xj.
bool IsTopOrLeftEdge(glm::dvec2 a, glm::dvec2 b);

// Depth test: LESS, or GREATER with reversed Z. Equal depth fails, so the earlier draw keeps it.
bool DepthPasses(double fragment, double stored, bool reversed_z);

// Coverage, depth and fragment operations for one triangle, any winding. A triangle of zero area
// (exactly, in double) or with a coordinate that is not finite draws nothing.
void DrawTriangle(TruthTarget& target, const WindowTriangle& triangle);

}  // namespace twinraster::truth
