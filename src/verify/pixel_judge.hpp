// The verifier's per-pixel stage: which pixel centres a bounded triangle or line certainly covers,
// may cover, or cannot, with its depth interval and the colours it allows there; and the frame's
// state that turns those offers into a PixelClass for each pixel.
#pragma once

#include "image/image.hpp"
#include "verify/allowed_colours.hpp"
#include "verify/bounded_geometry.hpp"
#include "verify/verification.hpp"

#include <glm/vec2.hpp>

#include <array>
#include <optional>

namespace twinraster::verify {

enum class Coverage : std::uint8_t { kOut, kMaybe, kIn };

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
  // [lo, hi] of the depth a fragment at p may get (float interpolation, D32).
  std::array<double, 2> Depth(glm::dvec2 p) const;
  ColourRange Colour(glm::dvec2 p, Rgb8 flat) const;
  // Signed distances from p to the edges v[i] -> v[i + 1], positive inside; degenerate: not valid.
  std::array<double, 3> EdgeDistances(glm::dvec2 p) const;
  bool Degenerate() const { return orientation_ == 0; }
  double radius() const { return radius_; }
  // How far edge i itself may move along its normal at a centre beside it.
  double EdgeRadius(int i) const { return edge_radius_[std::size_t(i)]; }

 private:
  std::array<WindowVertex, 3> v_;
  bool lit_ = false;
  double radius_ = 0;                 // how far a vertex may move (Euclidean)
  std::array<double, 3> edge_radius_{};     // edge i's endpoints' movement along its normal
  std::array<double, 3> outside_radius_{};  // any vertex's movement along edge i's normal
  int orientation_ = 0;               // sign of the area; 0: degenerate
  std::array<glm::dvec2, 3> normal_;  // unit, inward
  std::array<double, 3> offset_{};
  double area2_ = 0;  // twice the signed area
  glm::dvec2 gradient_{0.0};  // of depth
  double depth_error_ = 0, depth_relative_ = 0;
};

// One edge of a polygon drawn as a 1-pixel line (polygonMode LINE): a Bresenham, parallelogram or
// rectangle rasterization may each be used (strictLines false), so only centres near the segment's
// middle within half a pixel of it along the minor axis are certain.
class LineShape {
 public:
  LineShape(const WindowVertex& a, const WindowVertex& b, bool from_clipping);
  PixelBox Box(std::uint32_t width, std::uint32_t height) const;
  Coverage Covers(glm::dvec2 p) const;
  std::array<double, 2> Depth(glm::dvec2 p) const;
  ColourRange Colour(glm::dvec2, Rgb8 flat) const { return ColourRange::Exactly(flat); }  // lines are unlit

 private:
  WindowVertex a_, b_;
  bool from_clipping_ = false;
  double radius_ = 0;
  int major_ = 0;  // 0: x-major, 1: y-major
  double slope_ = 0;
  double depth_error_ = 0;
};

// The frame: pass 1 records, per pixel, the farthest depth of the nearest surface certain to be
// written there; pass 2 offers every surface that may cover a pixel and is not surely behind it.
class FrameJudge {
 public:
  FrameJudge(const Image& image, Rgb8 background, bool reversed_z);

  // Pass 1: a surface certainly covers (x, y) and its depth is in `depth`.
  void Occlude(int x, int y, std::array<double, 2> depth);
  // Pass 2: whether a surface that may cover (x, y) with this depth may also be what shows there.
  bool MayShow(int x, int y, std::array<double, 2> depth) const;
  void Offer(int x, int y, const ColourRange& colours);
  bool BackgroundMayShow(int x, int y) const { return occluder_[Index(x, y)] >= clear_key_; }
  Rgb8 background() const { return background_; }

  // The background where no surface is certain, then every pixel's class.
  Verification Finish(int subpixel_bits);
  Rgb8 ImageColour(int x, int y) const;
  std::uint32_t width() const { return image_->width; }
  std::uint32_t height() const { return image_->height; }

 private:
  std::size_t Index(int x, int y) const { return std::size_t(y) * image_->width + std::size_t(x); }
  const Image* image_;
  Rgb8 background_;
  bool reversed_ = false;
  double clear_key_ = 1;
  std::vector<double> occluder_;  // depth keys (negated when reversed), clear_key_: none certain
  struct State {
    ColourRange first;
    std::uint8_t offers = 0;    // saturates at 2
    bool uncertain = false;     // an offer that does not overlap the first
    std::uint8_t distance = 255;  // the image colour's distance from the nearest offer
  };
  std::vector<State> state_;
};

}  // namespace twinraster::verify
