#include "verify/bounded_geometry.hpp"

#include "truth/truth_clipping.hpp"

#include <cmath>
#include <limits>

namespace twinraster::verify {

namespace {

constexpr double kUnit = 0x1p-24;  // float's unit roundoff
constexpr double kInfinity = std::numeric_limits<double>::infinity();

bool IsFinite(const glm::dvec4& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z) && std::isfinite(v.w);
}

// The bound on truth::PlaneDistance's value for a vertex with this error.
double DistanceError(const glm::dvec4& e, int plane) {
  switch (plane) {
    case 0:
    case 1: return e.x + e.w;
    case 2:
    case 3: return e.y + e.w;
    case 4: return e.z;
    default: return e.z + e.w;
  }
}

// Where inside -> outside meets the plane, as the truth finds it; the error bound takes in both
// ends' and that of t = d_in / (d_in - d_out) in float.
BoundedVertex Intersect(const BoundedVertex& in, double d_in, const BoundedVertex& out, double d_out, int plane) {
  const double t = d_in / (d_in - d_out);
  const double t_error =
      (DistanceError(in.error, plane) + DistanceError(out.error, plane)) / std::abs(d_in - d_out) + 4 * kUnit;
  BoundedVertex v;
  v.clip = in.clip + t * (out.clip - in.clip);
  v.colour = in.colour + t * (out.colour - in.colour);
  v.error = glm::max(in.error, out.error) + glm::abs(out.clip - in.clip) * t_error +
            4 * kUnit * (glm::abs(in.clip) + glm::abs(out.clip));
  v.planes = (in.planes & out.planes) | (1u << plane);
  return v;
}

struct ClipPolygon {
  std::array<BoundedVertex, 9> v;
  std::size_t size = 0;
};

ClipPolygon ClipAgainst(const ClipPolygon& polygon, int plane) {
  ClipPolygon out;
  for (std::size_t i = 0; i < polygon.size; ++i) {
    const BoundedVertex& prev = polygon.v[(i + polygon.size - 1) % polygon.size];
    const BoundedVertex& cur = polygon.v[i];
    const double d_prev = truth::PlaneDistance(prev.clip, plane), d_cur = truth::PlaneDistance(cur.clip, plane);
    if (d_prev >= 0 && d_cur < 0) out.v[out.size++] = Intersect(prev, d_prev, cur, d_cur, plane);
    if (d_prev < 0 && d_cur >= 0) out.v[out.size++] = Intersect(cur, d_cur, prev, d_prev, plane);
    if (d_cur >= 0) out.v[out.size++] = cur;
  }
  if (out.size < 3) out.size = 0;
  return out;
}

// x / w through the viewport: the division's error (the spec allows 2.5 ULP), the inputs' and the
// viewport transform's, in pixels per unit of NDC `half`.
double WindowError(double c, double ce, double w, double we, double half, double window) {
  const double margin = std::abs(w) - we;
  if (!(margin > 0)) return kInfinity;
  return half * ((ce + std::abs(c / w) * we) / margin + 3 * kUnit * std::abs(c / w)) +
         4 * kUnit * (std::abs(window) + 2 * half);
}

// z / w, with viewport depth range [0, 1]: no scale, no offset.
double DepthError(double z, double ze, double w, double we) {
  const double margin = std::abs(w) - we;
  if (!(margin > 0)) return kInfinity;
  return (ze + std::abs(z / w) * we) / margin + 3 * kUnit * std::abs(z / w);
}

}  // namespace

void BoundVertices(const glm::mat4& float_f, const std::vector<glm::vec3>& float_positions,
                   std::vector<BoundedVertex>& out) {
  const glm::dmat4 f(float_f);
  const glm::dmat4 magnitude = glm::dmat4(glm::abs(f[0]), glm::abs(f[1]), glm::abs(f[2]), glm::abs(f[3]));
  out.assign(float_positions.size(), BoundedVertex{});
  for (std::size_t i = 0; i < float_positions.size(); ++i) {
    const glm::dvec4 p(glm::dvec3(float_positions[i]), 1.0);
    out[i].clip = f * p;  // exact but for double's rounding, 2^-29 of float's
    // Four products and three sums rounded in float: gamma_4 < 5u times the sum of |terms|.
    out[i].error = 5 * kUnit * (magnitude * glm::abs(p));
  }
}

bool InsideViewVolume(const BoundedVertex& v) {
  if (!IsFinite(v.clip)) return false;
  for (int plane = 0; plane < truth::kClipPlaneCount; ++plane) {
    if (truth::PlaneDistance(v.clip, plane) < 0) return false;
  }
  return true;
}

WindowVertex MapToWindow(const BoundedVertex& v, std::uint32_t width, std::uint32_t height, int subpixel_bits) {
  const double half_w = width / 2.0, half_h = height / 2.0;
  WindowVertex o;
  o.xy = {(v.clip.x / v.clip.w + 1.0) * half_w, (v.clip.y / v.clip.w + 1.0) * half_h};
  o.z = v.clip.z / v.clip.w;
  o.w = v.clip.w;
  o.colour = v.colour;
  const double ex = WindowError(v.clip.x, v.error.x, v.clip.w, v.error.w, half_w, o.xy.x);
  const double ey = WindowError(v.clip.y, v.error.y, v.clip.w, v.error.w, half_h, o.xy.y);
  o.xy_error = std::max(ex, ey) + std::ldexp(1.0, -subpixel_bits);  // any rounding to the subpixel grid
  o.z_error = DepthError(v.clip.z, v.error.z, v.clip.w, v.error.w);
  return o;
}

WindowPolygon ClipToWindow(const BoundedVertex& a, const BoundedVertex& b, const BoundedVertex& c, std::uint32_t width,
                           std::uint32_t height, int subpixel_bits, ClipVolume volume) {
  WindowPolygon window;
  if (!IsFinite(a.clip) || !IsFinite(b.clip) || !IsFinite(c.clip)) return window;
  ClipPolygon polygon;
  polygon.v[0] = a, polygon.v[1] = b, polygon.v[2] = c;
  polygon.size = 3;
  const int first_plane = volume == ClipVolume::kView ? 0 : 4;  // planes 4 and 5 bound z
  for (int plane = first_plane; plane < truth::kClipPlaneCount && polygon.size > 0; ++plane) {
    polygon = ClipAgainst(polygon, plane);
  }
  for (std::size_t i = 0; i < polygon.size; ++i) {
    window.v[i] = MapToWindow(polygon.v[i], width, height, subpixel_bits);
    window.edge_from_clipping[i] = (polygon.v[i].planes & polygon.v[(i + 1) % polygon.size].planes) != 0;
  }
  window.size = polygon.size;
  return window;
}

}  // namespace twinraster::verify
