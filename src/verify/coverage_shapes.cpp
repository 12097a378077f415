#include "verify/coverage_shapes.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace twinraster::verify {

namespace {

double Cross(glm::dvec2 a, glm::dvec2 b) { return a.x * b.y - a.y * b.x; }

double SegmentDistance(glm::dvec2 p, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a;
  const double length2 = glm::dot(ab, ab);
  const double t = length2 > 0 ? std::clamp(glm::dot(p - a, ab) / length2, 0.0, 1.0) : 0.0;
  return glm::length(p - (a + t * ab));
}

PixelBox BoxOf(double x0, double y0, double x1, double y1, std::uint32_t width, std::uint32_t height) {
  // Pixel centres px + 0.5 inside [x0, x1].
  const auto first = [](double lo, std::uint32_t n) {
    return lo <= 0 ? 0 : lo >= n ? int(n) : int(std::ceil(lo - 0.5));
  };
  const auto last = [](double hi, std::uint32_t n) {
    return hi < 0.5 ? -1 : hi >= n ? int(n) - 1 : int(std::floor(hi - 0.5));
  };
  if (!(x0 <= x1) || !(y0 <= y1)) return {};
  return {first(x0, width), first(y0, height), last(x1, width), last(y1, height)};
}

std::uint8_t ToUnorm(double v, bool up) {
  const double s = std::clamp(v, 0.0, 1.0) * 255.0;
  return static_cast<std::uint8_t>(up ? std::ceil(s) : std::floor(s));
}

// Light and interpolation in float: a relative error far below one step of 255, widened so the
// UNORM conversion may round either way.
constexpr double kColourSlack = 1e-4;

}  // namespace

TriangleShape::TriangleShape(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, bool lit)
    : v_{a, b, c}, lit_(lit) {
  radius_ = std::sqrt(2.0) * std::max({a.xy_error, b.xy_error, c.xy_error});
  const glm::dvec2 e1 = b.xy - a.xy, e2 = c.xy - a.xy;
  area2_ = Cross(e1, e2);
  orientation_ = area2_ > 0 ? 1 : area2_ < 0 ? -1 : 0;
  for (std::size_t i = 0; i < 3 && orientation_ != 0; ++i) {
    const glm::dvec2 d = v_[(i + 1) % 3].xy - v_[i].xy;
    if (!(glm::dot(d, d) > 0)) orientation_ = 0;  // a zero length (its square root is 0 too)
  }
  const double z_error = std::max({a.z_error, b.z_error, c.z_error});
  const double z_max = std::max({std::abs(a.z), std::abs(b.z), std::abs(c.z)});
  if (orientation_ != 0) {
    // The depth plane z = a.z + g · (p - a), and how ill-conditioned it is in float.
    const double dz1 = b.z - a.z, dz2 = c.z - a.z;
    gradient_ = glm::dvec2(dz1 * e2.y - dz2 * e1.y, dz2 * e1.x - dz1 * e2.x) / area2_;
    const double condition = (std::abs(e1.x * e2.y) + std::abs(e1.y * e2.x)) / std::abs(area2_);
    // Vertices that moved by up to `radius` move the plane by |g| radius at a covered centre.
    depth_error_ = z_error + glm::length(gradient_) * radius_ + 4 * kFloatUnit * z_max;
    depth_relative_ = 4 * kFloatUnit + 8 * kFloatUnit * condition;
  } else {
    depth_error_ = z_error + 4 * kFloatUnit * z_max;
  }
}

const TriangleShape::Edges& TriangleShape::edges() const {
  if (edges_made_ || orientation_ == 0) return edges_;
  edges_made_ = true;
  const double error = std::max({v_[0].xy_error, v_[1].xy_error, v_[2].xy_error});
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::dvec2 p = v_[i].xy, q = v_[(i + 1) % 3].xy;
    const double length = glm::length(q - p);
    // Inside: orientation * cross(q - p, x - p) > 0.
    edges_.normal[i] = double(orientation_) * glm::dvec2(-(q.y - p.y), q.x - p.x) / length;
    edges_.offset[i] = -glm::dot(edges_.normal[i], p);
    // A vertex moved by up to e along x and along y moves by up to e (|n.x| + |n.y|) along n.
    const double along_normal = std::abs(edges_.normal[i].x) + std::abs(edges_.normal[i].y);
    edges_.edge_radius[i] = std::max(v_[i].xy_error, v_[(i + 1) % 3].xy_error) * along_normal;
    edges_.outside_radius[i] = error * along_normal;
    edges_.inverse_x[i] = edges_.normal[i].x != 0 ? 1.0 / edges_.normal[i].x : 0.0;
  }
  return edges_;
}

PixelBox TriangleShape::Box(std::uint32_t width, std::uint32_t height) const {
  const double x0 = std::min({v_[0].xy.x, v_[1].xy.x, v_[2].xy.x}) - radius_;
  const double x1 = std::max({v_[0].xy.x, v_[1].xy.x, v_[2].xy.x}) + radius_;
  const double y0 = std::min({v_[0].xy.y, v_[1].xy.y, v_[2].xy.y}) - radius_;
  const double y1 = std::max({v_[0].xy.y, v_[1].xy.y, v_[2].xy.y}) + radius_;
  return BoxOf(x0, y0, x1, y1, width, height);
}

Coverage TriangleShape::Covers(glm::dvec2 p) const {
  if (!std::isfinite(radius_)) return Coverage::kMaybe;
  if (orientation_ != 0) {
    const Edges& e = edges();
    const double d0 = glm::dot(e.normal[0], p) + e.offset[0];
    const double d1 = glm::dot(e.normal[1], p) + e.offset[1];
    const double d2 = glm::dot(e.normal[2], p) + e.offset[2];
    // Inside by more than its edge can move: inside whatever the implementation does. Beyond one
    // edge by more than any vertex can move along its normal: outside.
    if (d0 > e.edge_radius[0] && d1 > e.edge_radius[1] && d2 > e.edge_radius[2]) return Coverage::kIn;
    if (d0 < -e.outside_radius[0] || d1 < -e.outside_radius[1] || d2 < -e.outside_radius[2]) return Coverage::kOut;
    if (d0 >= 0 && d1 >= 0 && d2 >= 0) return Coverage::kMaybe;
  }
  const double distance = std::min({SegmentDistance(p, v_[0].xy, v_[1].xy), SegmentDistance(p, v_[1].xy, v_[2].xy),
                                    SegmentDistance(p, v_[2].xy, v_[0].xy)});
  return distance <= radius_ ? Coverage::kMaybe : Coverage::kOut;
}

std::array<double, 2> TriangleShape::DepthRange() const {
  const double lo = std::min({v_[0].z, v_[1].z, v_[2].z}), hi = std::max({v_[0].z, v_[1].z, v_[2].z});
  if (orientation_ == 0 || !std::isfinite(radius_)) {
    const double e = std::isfinite(radius_) ? depth_error_ : std::numeric_limits<double>::infinity();
    return {lo - e, hi + e};
  }
  // Within the triangle the plane stays between its corners; within `radius` outside it, it moves
  // |g| radius further. Depth(p)'s own widening, bounded over the box.
  const double extent =
      (std::abs(gradient_.x) + std::abs(gradient_.y)) *
      (std::max({v_[0].xy.x, v_[1].xy.x, v_[2].xy.x}) - std::min({v_[0].xy.x, v_[1].xy.x, v_[2].xy.x}) +
       std::max({v_[0].xy.y, v_[1].xy.y, v_[2].xy.y}) - std::min({v_[0].xy.y, v_[1].xy.y, v_[2].xy.y}) + 2 * radius_);
  const double e = depth_error_ + glm::length(gradient_) * radius_ + depth_relative_ * extent +
                   4 * kFloatUnit * std::max(std::abs(lo), std::abs(hi)) + 4 * kFloatUnit * extent;
  return {lo - e, hi + e};
}

namespace {

// The pixels whose centres lie in [lo, hi] of a row, shrunk (inner) or grown (outer) by a margin
// far above the rounding of the arithmetic that found lo and hi, as {first, last}; first > last
// when there are none.
std::array<int, 2> PixelsWithin(double lo, double hi, bool inner) {
  const double margin = 1e-6 * (1.0 + std::max(std::abs(lo), std::abs(hi)));
  lo = inner ? lo + margin : lo - margin;
  hi = inner ? hi - margin : hi + margin;
  lo = std::max(lo, -1.0), hi = std::min(hi, 1e8);
  if (!(lo < hi)) return {1, 0};
  return inner ? std::array<int, 2>{int(std::floor(lo - 0.5)) + 1, int(std::ceil(hi - 0.5)) - 1}
               : std::array<int, 2>{int(std::floor(lo - 0.5)), int(std::ceil(hi - 0.5))};
}

}  // namespace

TriangleShape::RowSpans TriangleShape::Spans(int y) const {
  if (orientation_ == 0 || !std::isfinite(radius_))
    return {{std::numeric_limits<int>::min(), std::numeric_limits<int>::max()}, {1, 0}};
  // Per edge, the centres X = x + 0.5 with normal . (X, y) + offset + bias > 0 (inside: bias the
  // edge's own radius, negated) or >= 0 (reach: bias the radius outside it).
  const Edges& e = edges();
  const double centre_y = y + 0.5;
  double in_lo = -1e9, in_hi = 1e9, out_lo = -1e9, out_hi = 1e9;
  bool in_none = false, out_none = false;
  for (std::size_t i = 0; i < 3; ++i) {
    const double a = e.normal[i].x, base = e.normal[i].y * centre_y + e.offset[i];
    const double inner = base - e.edge_radius[i], outer = base + e.outside_radius[i];
    if (a > 0) {
      in_lo = std::max(in_lo, -inner * e.inverse_x[i]), out_lo = std::max(out_lo, -outer * e.inverse_x[i]);
    } else if (a < 0) {
      in_hi = std::min(in_hi, -inner * e.inverse_x[i]), out_hi = std::min(out_hi, -outer * e.inverse_x[i]);
    } else {
      in_none = in_none || !(inner > 0), out_none = out_none || outer < 0;
    }
  }
  // The inside span's margin leaves the pixels at its ends to Covers.
  return {out_none ? std::array<int, 2>{1, 0} : PixelsWithin(out_lo, out_hi, false),
          in_none ? std::array<int, 2>{1, 0} : PixelsWithin(in_lo, in_hi, true)};
}

std::array<double, 3> TriangleShape::EdgeDistances(glm::dvec2 p) const {
  const Edges& e = edges();
  return {glm::dot(e.normal[0], p) + e.offset[0], glm::dot(e.normal[1], p) + e.offset[1],
          glm::dot(e.normal[2], p) + e.offset[2]};
}

std::array<double, 2> TriangleShape::DepthAnywhere() const {
  const double lo = std::min({v_[0].z, v_[1].z, v_[2].z}), hi = std::max({v_[0].z, v_[1].z, v_[2].z});
  const double e = std::isfinite(radius_) ? depth_error_ : std::numeric_limits<double>::infinity();
  return {lo - e, hi + e};
}

std::array<double, 2> TriangleShape::DepthAlong(int y, int x0, int x1) const {
  if (orientation_ == 0 || !std::isfinite(radius_)) return DepthAnywhere();
  // Along a row, the plane is linear and Depth's error convex, so both ends bound every centre
  // between them, but for the rounding of Depth's own arithmetic there: a few units in the last
  // place of its largest term, widened here by far more.
  const glm::dvec2 a(x0 + 0.5, y + 0.5), b(x1 + 0.5, y + 0.5);
  const std::array<double, 2> at_a = Depth(a), at_b = Depth(b);
  const double size = std::abs(v_[0].z) +
                      std::abs(gradient_.x) * std::max(std::abs(a.x - v_[0].xy.x), std::abs(b.x - v_[0].xy.x)) +
                      std::abs(gradient_.y * (a.y - v_[0].xy.y)) + std::max(at_a[1] - at_a[0], at_b[1] - at_b[0]);
  const double margin = 0x1p-40 * size;
  return {std::min(at_a[0], at_b[0]) - margin, std::max(at_a[1], at_b[1]) + margin};
}

const TriangleShape::Perspective& TriangleShape::perspective() const {
  if (perspective_made_) return perspective_;
  perspective_made_ = true;
  // Each barycentric coordinate is affine in the point, l_k(q) = l_k(v0) + grad l_k . (q - v0), and so
  // are both sums, taken from v0 where l0 is 1 and the others 0.
  const std::array<glm::dvec2, 3> grad{glm::dvec2(v_[1].xy.y - v_[2].xy.y, v_[2].xy.x - v_[1].xy.x) / area2_,
                                       glm::dvec2(v_[2].xy.y - v_[0].xy.y, v_[0].xy.x - v_[2].xy.x) / area2_,
                                       glm::dvec2(v_[0].xy.y - v_[1].xy.y, v_[1].xy.x - v_[0].xy.x) / area2_};
  Perspective& s = perspective_;
  s.colour0 = v_[0].colour / v_[0].w, s.weight0 = 1.0 / v_[0].w;
  for (std::size_t k = 0; k < 3; ++k) {
    const glm::dvec2 g = grad[k] / v_[k].w;
    s.colour_dx += g.x * v_[k].colour, s.colour_dy += g.y * v_[k].colour;
    s.weight_dx += g.x, s.weight_dy += g.y;
  }
  return s;
}

ColourRange TriangleShape::LitColour(glm::dvec2 p) const {
  glm::dvec3 lo(1.0), hi(0.0);
  const auto take = [&](glm::dvec3 c) {
    lo = glm::min(lo, c);
    hi = glm::max(hi, c);
  };
  if (orientation_ == 0 || !std::isfinite(radius_)) {
    for (const WindowVertex& v : v_) take(v.colour);
  } else {
    // Perspective-correct interpolation, sum(l_k c_k / w_k) / sum(l_k / w_k), at p and where p may
    // lie relative to moved vertices.
    const Perspective& s = perspective();
    const double r = radius_;
    const glm::dvec2 d = p - v_[0].xy;
    const glm::dvec3 colour = s.colour0 + s.colour_dx * d.x + s.colour_dy * d.y;
    const double weight = s.weight0 + s.weight_dx * d.x + s.weight_dy * d.y;
    const std::array<glm::dvec4, 5> at{glm::dvec4(colour, weight),
                                       glm::dvec4(colour + r * s.colour_dx, weight + r * s.weight_dx),
                                       glm::dvec4(colour - r * s.colour_dx, weight - r * s.weight_dx),
                                       glm::dvec4(colour + r * s.colour_dy, weight + r * s.weight_dy),
                                       glm::dvec4(colour - r * s.colour_dy, weight - r * s.weight_dy)};
    for (const glm::dvec4& q : at) {
      if (!(std::abs(q.w) > 0)) {
        for (const WindowVertex& v : v_) take(v.colour);
        continue;
      }
      take(glm::dvec3(q) * (1.0 / q.w));
    }
  }
  lo -= kColourSlack, hi += kColourSlack;
  return {{ToUnorm(lo.x, false), ToUnorm(lo.y, false), ToUnorm(lo.z, false)},
          {ToUnorm(hi.x, true), ToUnorm(hi.y, true), ToUnorm(hi.z, true)}};
}

namespace {

// The part of a -> b inside [0, W] x [0, H], as fractions {from, to}; from > to when none is.
std::array<double, 2> InsideCanvas(glm::dvec2 a, glm::dvec2 b, std::uint32_t width, std::uint32_t height) {
  double from = 0, to = 1;
  const glm::dvec2 d = b - a;
  const auto keep = [&](double start, double delta, double limit) {  // start + t delta <= limit
    if (delta == 0) {
      if (start > limit) from = 2, to = -1;
      return;
    }
    const double t = (limit - start) / delta;
    if (delta > 0)
      to = std::min(to, t);
    else
      from = std::max(from, t);
  };
  keep(a.x, d.x, double(width)), keep(-a.x, -d.x, 0.0), keep(a.y, d.y, double(height)), keep(-a.y, -d.y, 0.0);
  return {from, to};
}

}  // namespace

LineShape::LineShape(const WindowVertex& a, const WindowVertex& b, bool from_clipping, LineRules rules,
                     std::uint32_t width, std::uint32_t height)
    : a_(a), b_(b), from_clipping_(from_clipping), rules_(rules) {
  // Each endpoint may move by its own error; a strict line's corners are then offset from it and
  // rounded to the subpixel grid again, which may move them as much once more.
  const double corners = rules == LineRules::kStrict ? 2.0 : 1.0;
  radius_a_ = corners * std::sqrt(2.0) * a.xy_error;
  radius_b_ = corners * std::sqrt(2.0) * b.xy_error;
  radius_ = std::max(radius_a_, radius_b_);
  length_ = glm::length(b.xy - a.xy);
  if (length_ > 0) direction_ = (b.xy - a.xy) / length_;
  canvas_ = InsideCanvas(a.xy, b.xy, width, height);
  const glm::dvec2 d = glm::abs(b.xy - a.xy);
  major_ = d.x >= d.y ? 0 : 1;
  const double along = major_ == 0 ? d.x : d.y, across = major_ == 0 ? d.y : d.x;
  slope_ = along > 0 ? across / along : 0;
  const double z_max = std::max(std::abs(a.z), std::abs(b.z));
  // Depth is interpolated along the line; which pixel gets which fraction may shift by up to a
  // pixel (plus the vertices' movement).
  const double depth_slope = along > 0 ? std::abs(b.z - a.z) / along : std::abs(b.z - a.z);
  depth_error_ = std::max(a.z_error, b.z_error) + depth_slope * (1 + 2 * radius_) + 4 * kFloatUnit * z_max;
}

PixelBox LineShape::Box(std::uint32_t width, std::uint32_t height) const {
  const double m = 1.5 + 2 * radius_;
  return BoxOf(std::min(a_.xy.x, b_.xy.x) - m, std::min(a_.xy.y, b_.xy.y) - m, std::max(a_.xy.x, b_.xy.x) + m,
               std::max(a_.xy.y, b_.xy.y) + m, width, height);
}

Coverage LineShape::Covers(glm::dvec2 p) const {
  if (!std::isfinite(radius_)) return Coverage::kMaybe;
  return rules_ == LineRules::kStrict ? CoversStrict(p) : CoversNotStrict(p);
}

// The rectangle: certain more than the endpoints' movement inside its long sides and inside its
// square ends, where the ends are the endpoints or the canvas's border (a line may be clipped there,
// or at a guard band, or not at all).
Coverage LineShape::CoversStrict(glm::dvec2 p) const {
  if (SegmentDistance(p, a_.xy, b_.xy) > 0.5 + radius_) return Coverage::kOut;
  if (from_clipping_ || !(length_ > 0)) return Coverage::kMaybe;
  const glm::dvec2 ap = p - a_.xy;
  const double s = glm::dot(ap, direction_), across = std::abs(Cross(direction_, ap));
  const double t = std::clamp(s / length_, 0.0, 1.0);
  // The moved segment passes within this of the point of the segment beside p.
  if (across >= 0.5 - ((1 - t) * radius_a_ + t * radius_b_)) return Coverage::kMaybe;
  // Along the moved segment, p's place shifts by the endpoints' movement and by the turn of the
  // segment (at most their sum over its length) times how far p lies from it.
  const double turn = (radius_a_ + radius_b_) / length_;
  const double along = 2 * radius_ + 0.5 * turn + 0.5 * turn * turn * length_;
  if (s <= canvas_[0] * length_ + along || s >= canvas_[1] * length_ - along) return Coverage::kMaybe;
  return Coverage::kIn;
}

// A Bresenham, parallelogram or rectangle rasterization may each be used: only centres within half
// a pixel of the segment along the minor axis, more than a pixel from its ends (or the canvas's
// border), are certain.
Coverage LineShape::CoversNotStrict(glm::dvec2 p) const {
  const int minor = 1 - major_;
  const double a_major = a_.xy[major_], b_major = b_.xy[major_];
  const double low = std::min(a_major, b_major), high = std::max(a_major, b_major);
  const double r = 2 * radius_;
  if (p[major_] < low - 1 - r || p[major_] > high + 1 + r) return Coverage::kOut;
  if (p[major_] < low || p[major_] > high) {
    // Beyond an end: the diamond-exit rule and the parallelogram may both reach a pixel further.
    const double end = std::min(glm::length(p - a_.xy), glm::length(p - b_.xy));
    return end <= 1 + r ? Coverage::kMaybe : Coverage::kOut;
  }
  const double t = high > low ? (p[major_] - a_major) / (b_major - a_major) : 0.0;
  const double across = std::abs(p[minor] - (a_.xy[minor] + t * (b_.xy[minor] - a_.xy[minor])));
  const double c0 = a_major + canvas_[0] * (b_major - a_major), c1 = a_major + canvas_[1] * (b_major - a_major);
  const bool inside_ends =
      canvas_[0] <= canvas_[1] && p[major_] > std::min(c0, c1) + 1 + r && p[major_] < std::max(c0, c1) - 1 - r;
  if (!from_clipping_ && inside_ends && across < 0.5 - r * (1 + slope_)) return Coverage::kIn;
  // A strict line is a rectangle one pixel wide: up to sqrt(1 + slope^2) / 2 along the minor axis.
  return across <= 0.5 * std::sqrt(1 + slope_ * slope_) + r * (1 + slope_) ? Coverage::kMaybe : Coverage::kOut;
}

std::array<double, 2> LineShape::DepthRange() const {
  return {std::min(a_.z, b_.z) - depth_error_, std::max(a_.z, b_.z) + depth_error_};
}

std::array<double, 2> LineShape::Depth(glm::dvec2 p) const {
  const double a_major = a_.xy[major_], b_major = b_.xy[major_];
  const double t = b_major != a_major ? std::clamp((p[major_] - a_major) / (b_major - a_major), 0.0, 1.0) : 0.0;
  const double z = a_.z + t * (b_.z - a_.z);
  if (!std::isfinite(radius_)) return {std::min(a_.z, b_.z) - depth_error_, std::max(a_.z, b_.z) + depth_error_};
  return {z - depth_error_, z + depth_error_};
}

}  // namespace twinraster::verify
