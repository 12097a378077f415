#include "truth/truth_clipping.hpp"

#include <cmath>

namespace twinraster::truth {

namespace {

bool IsFinite(const glm::dvec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

const glm::dvec4& Position(const glm::dvec4& v) { return v; }
const glm::dvec4& Position(const LitVertex& v) { return v.clip; }

// Where edge inside -> outside meets the plane. Always interpolated from the inside end, so that
// the two triangles sharing an edge create the very same vertex on it.
glm::dvec4 Intersect(const glm::dvec4& inside, double d_inside, const glm::dvec4& outside, double d_outside) {
  const double t = d_inside / (d_inside - d_outside);  // d_inside >= 0 > d_outside: t in [0, 1)
  return inside + t * (outside - inside);
}
LitVertex Intersect(const LitVertex& inside, double d_inside, const LitVertex& outside, double d_outside) {
  const double t = d_inside / (d_inside - d_outside);
  return {inside.clip + t * (outside.clip - inside.clip), inside.colour + t * (outside.colour - inside.colour)};
}

template <class Vertex>
std::vector<Vertex> ClipPolygonAgainstPlane(const std::vector<Vertex>& polygon, int plane) {
  std::vector<Vertex> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i) {
    const Vertex& prev = polygon[(i + n - 1) % n];
    const Vertex& cur = polygon[i];
    const double d_prev = PlaneDistance(Position(prev), plane), d_cur = PlaneDistance(Position(cur), plane);
    if (d_prev >= 0 && d_cur < 0) out.push_back(Intersect(prev, d_prev, cur, d_cur));  // leaving
    if (d_prev < 0 && d_cur >= 0) out.push_back(Intersect(cur, d_cur, prev, d_prev));  // entering
    if (d_cur >= 0) out.push_back(cur);
  }
  if (out.size() < 3) out.clear();
  return out;
}

template <class Vertex>
std::vector<Vertex> ClipTriangle(const Vertex& a, const Vertex& b, const Vertex& c) {
  if (!IsFinite(Position(a)) || !IsFinite(Position(b)) || !IsFinite(Position(c))) return {};
  // A plane every vertex is inside of leaves the polygon as it is, so clipping against all six
  // gives what clipping against the outcodes' planes only would.
  std::vector<Vertex> polygon{a, b, c};
  for (int plane = 0; plane < kClipPlaneCount && !polygon.empty(); ++plane) {
    polygon = ClipPolygonAgainstPlane(polygon, plane);
  }
  return polygon;
}

}  // namespace

double PlaneDistance(const glm::dvec4& clip, int plane) {
  switch (plane) {
    case 0: return clip.w - clip.x;
    case 1: return clip.w + clip.x;
    case 2: return clip.w - clip.y;
    case 3: return clip.w + clip.y;
    case 4: return clip.z;
    default: return clip.w - clip.z;
  }
}

ClipPolygon ClipAgainstPlane(const ClipPolygon& polygon, int plane) { return ClipPolygonAgainstPlane(polygon, plane); }

ClipPolygon ClipToViewVolume(const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c) {
  return ClipTriangle(a, b, c);
}

LitPolygon ClipToViewVolume(const LitVertex& a, const LitVertex& b, const LitVertex& c) {
  return ClipTriangle(a, b, c);
}

}  // namespace twinraster::truth
