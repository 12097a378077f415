// Which pixel centres a bounded triangle or line certainly covers, may cover, or cannot, with the
// depth interval a fragment may get there and the colours it allows. One primitive at a time: it
// keeps no frame state and does not decide what shows at a pixel (pixel_judge.hpp does).
#pragma once

#include "verify/allowed_colours.hpp"
#include "verify/bounded_geometry.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cmath>
#include <cstdint>

namespace twinraster::verify {

enum class Coverage : std::uint8_t { kOut, kMaybe, kIn };

// The relative error of one rounding to float (unit roundoff): what each float operation of the
// device's may add.
inline constexpr double kFloatUnit = 0x1p-24;

struct PixelBox {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;  // inclusive
  bool Empty() const { return x1 < x0 || y1 < y0; }
};

// A filled triangle whose vertices may each move by up to `radius` (Euclidean). A centre farther
// than that inside every edge is covered whatever the implementation does, one farther than that
// from the whole triangle is not; between, any consistent tie rule or snapping may decide.
class TriangleShape {
 public:
  TriangleShape(const WindowVertex& a, const WindowVertex& b, const WindowVertex& c, bool lit);
  PixelBox Box(std::uint32_t width, std::uint32_t height) const;
  Coverage Covers(glm::dvec2 p) const;
  // [lo, hi] of the depth a fragment at p may get (float interpolation, D32). Inline, as Colour:
  // the verifier asks both at nearly every pixel it judges.
  std::array<double, 2> Depth(glm::dvec2 p) const {
    if (orientation_ == 0 || !std::isfinite(radius_)) return DepthAnywhere();
    const glm::dvec2 d = p - v_[0].xy;
    const double gx = gradient_.x * d.x, gy = gradient_.y * d.y;
    const double z = v_[0].z + gx + gy;
    const double e = depth_error_ + depth_relative_ * (std::abs(gx) + std::abs(gy)) + 4 * kFloatUnit * std::abs(z);
    return {z - e, z + e};
  }
  ColourRange Colour(glm::dvec2 p, Rgb8 flat) const { return lit_ ? LitColour(p) : ColourRange::Exactly(flat); }
  // Bounds on the depth of any fragment it may make, anywhere.
  std::array<double, 2> DepthRange() const;
  // Bounds on Depth(p) at every centre of row y's pixels x0..x1.
  std::array<double, 2> DepthAlong(int y, int x0, int x1) const;
  // Row y's pixels as {first, last} (first > last when none): `reach`, those it may cover at all
  // (Covers says kOut for every other one), and `inside`, those whose centres are inside by more
  // than any edge can move (Covers says kIn). Scanning skips the edge tests inside.
  struct RowSpans {
    std::array<int, 2> reach, inside;
  };
  RowSpans Spans(int y) const;
  // Signed distances from p to the edges v[i] -> v[i + 1], positive inside; degenerate: not valid.
  std::array<double, 3> EdgeDistances(glm::dvec2 p) const;
  bool Degenerate() const { return orientation_ == 0; }
  bool lit() const { return lit_; }  // its colour varies over it (else its flat colour everywhere)
  double radius() const { return radius_; }
  // How far edge i itself may move along its normal at a centre beside it.
  double EdgeRadius(int i) const { return edges().edge_radius[std::size_t(i)]; }

 private:
  // The edges' lines and how far each may move. Made on first use: most triangles of a large
  // scene are passed over by their box and depth range alone, before any centre is tested.
  struct Edges {
    std::array<glm::dvec2, 3> normal;  // unit, inward
    std::array<double, 3> offset{};
    std::array<double, 3> edge_radius{};     // edge i's endpoints' movement along its normal
    std::array<double, 3> outside_radius{};  // any vertex's movement along edge i's normal
    std::array<double, 3> inverse_x{};       // 1 / normal.x, 0 where that is 0
  };
  const Edges& edges() const;
  // Perspective-correct colour's numerator and denominator, both affine in the pixel: their values
  // at v0 and their slopes. Made on first use, as only lit triangles that may show need them.
  struct Perspective {
    glm::dvec3 colour0{0.0}, colour_dx{0.0}, colour_dy{0.0};
    double weight0 = 0, weight_dx = 0, weight_dy = 0;
  };
  const Perspective& perspective() const;
  std::array<double, 2> DepthAnywhere() const;  // Depth where the plane is unknown: its corners' range
  ColourRange LitColour(glm::dvec2 p) const;

  std::array<WindowVertex, 3> v_;
  bool lit_ = false;
  double radius_ = 0;    // how far a vertex may move (Euclidean)
  int orientation_ = 0;  // sign of the area; 0: degenerate
  mutable bool edges_made_ = false;
  mutable Edges edges_;
  mutable bool perspective_made_ = false;
  mutable Perspective perspective_;
  double area2_ = 0;          // twice the signed area
  glm::dvec2 gradient_{0.0};  // of depth
  double depth_error_ = 0, depth_relative_ = 0;
};

// How the device draws 1-pixel lines (polygonMode LINE; twinraster sets no line rasterization
// state, so the device's default mode). Strict: the rectangle of Basic Line Segment Rasterization,
// half a pixel either side of the segment and ending square at its endpoints. Not strict: that
// rectangle, the non-strict parallelogram or a Bresenham rasterization, whichever the device uses.
enum class LineRules { kNotStrict, kStrict };

// One edge of a polygon drawn as a 1-pixel line. `a` and `b` are the edge clipped by depth only
// (ClipVolume::kDepth): the part inside the canvas, [canvas_from, canvas_to] as fractions of a -> b,
// is where a pixel may be certain; beyond the canvas the edge may be clipped anywhere or not at all.
class LineShape {
 public:
  LineShape(const WindowVertex& a, const WindowVertex& b, bool from_clipping, LineRules rules, std::uint32_t width,
            std::uint32_t height);
  PixelBox Box(std::uint32_t width, std::uint32_t height) const;
  Coverage Covers(glm::dvec2 p) const;
  std::array<double, 2> Depth(glm::dvec2 p) const;
  ColourRange Colour(glm::dvec2, Rgb8 flat) const { return ColourRange::Exactly(flat); }  // lines are unlit
  std::array<double, 2> DepthRange() const;

 private:
  Coverage CoversStrict(glm::dvec2 p) const;
  Coverage CoversNotStrict(glm::dvec2 p) const;

  WindowVertex a_, b_;
  bool from_clipping_ = false;
  LineRules rules_ = LineRules::kNotStrict;
  double radius_ = 0;  // how far either endpoint may move (Euclidean)
  double radius_a_ = 0, radius_b_ = 0;
  double length_ = 0;
  glm::dvec2 direction_{1, 0};          // unit, a -> b
  std::array<double, 2> canvas_{0, 0};  // the part inside the canvas, as fractions of a -> b
  int major_ = 0;                       // 0: x-major, 1: y-major
  double slope_ = 0;
  double depth_error_ = 0;
};

}  // namespace twinraster::verify
