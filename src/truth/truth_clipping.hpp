// The truth's clipping stage: Sutherland-Hodgman in double against the twin's view volume
// (cpu/lavapipe/clipping.hpp: with a depth attachment there is no guard band), -w <= x <= w,
// -w <= y <= w, 0 <= z <= w. Nothing is rounded to float.
#pragma once

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <vector>

namespace twinraster::truth {

// Planes in the twin's order: x <= w, x >= -w, y <= w, y >= -w, z >= 0, z <= w.
constexpr int kClipPlaneCount = 6;

// Signed distance of a clip position to `plane` (0 .. 5): >= 0 is inside.
double PlaneDistance(const glm::dvec4& clip, int plane);

using ClipPolygon = std::vector<glm::dvec4>;  // convex, vertices in order

// One Sutherland-Hodgman pass: the part of `polygon` inside `plane` (fewer than 3 vertices: none).
ClipPolygon ClipAgainstPlane(const ClipPolygon& polygon, int plane);

// The triangle's part inside the view volume, as a polygon to draw as the fan (p0, p[i-1], p[i]).
// Empty if nothing is inside or a coordinate is not finite.
ClipPolygon ClipToViewVolume(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c);

// A vertex with a Gouraud colour: the colour is interpolated along with the clip position (linear
// in clip space is exactly what perspective-correct interpolation needs).
struct LitVertex {
  glm::dvec4 clip{0.0};
  glm::dvec3 colour{0.0};
};
using LitPolygon = std::vector<LitVertex>;

// ClipToViewVolume for a triangle with corner colours.
LitPolygon ClipToViewVolume(const LitVertex& a, const LitVertex& b, const LitVertex& c);

}  // namespace twinraster::truth
