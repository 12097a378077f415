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
  // Bounds on the depth of any fragment it may make, anywhere.
  std::array<double, 2> DepthRange() const;
  // The pixels of row y whose centres are inside by more than any edge can move (Covers says kIn),
  // as {first, last}; first > last when there are none. Scanning skips the edge tests there.
  std::array<int, 2> InsideSpan(int y) const;
  // The pixels of row y that it may cover at all: Covers says kOut for every other one.
  std::array<int, 2> ReachSpan(int y) const;
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
  double radius_ = 0;              // how far either endpoint may move (Euclidean)
  double radius_a_ = 0, radius_b_ = 0;
  double length_ = 0;
  glm::dvec2 direction_{1, 0};     // unit, a -> b
  std::array<double, 2> canvas_{0, 0};  // the part inside the canvas, as fractions of a -> b
  int major_ = 0;  // 0: x-major, 1: y-major
  double slope_ = 0;
  double depth_error_ = 0;
};

// A band of the frame's rows [row0, row1): pass 1 records, per pixel, the farthest depth of the
// nearest surface certain to be written there; pass 2 offers every surface that may cover a
// pixel and is not surely behind it. Bands share nothing, so each may run on its own thread.
class FrameJudge {
 public:
  FrameJudge(const Image& image, Rgb8 background, bool reversed_z, int row0, int row1);
  ~FrameJudge();  // hands its per-pixel buffers back for the next frame
  FrameJudge(const FrameJudge&) = delete;
  FrameJudge& operator=(const FrameJudge&) = delete;

  PixelBox Clip(PixelBox box) const;  // to this band's rows
  // Pass 1: a surface certainly covers (x, y) and its depth is in `depth`.
  void Occlude(int x, int y, std::array<double, 2> depth);
  // Pass 2: whether a surface that may cover (x, y) with this depth may also be what shows there.
  bool MayShow(int x, int y, std::array<double, 2> depth) const;
  // `certain_line`: a line certain to cover (x, y) offers it (see Verification's shared edges).
  void Offer(int x, int y, const ColourRange& colours, bool certain_line = false);
  bool BackgroundMayShow(int x, int y) const { return gap_[Index(x, y)] == 0; }
  Rgb8 background() const { return background_; }

  // Whether a surface whose depth lies in `range` everywhere could matter anywhere in `box`: in
  // pass 1 lower the bound (`showing` false), in pass 2 show (`showing` true). Decided per 16 x 16
  // tile from the farthest bound in it, as of the last RefreshTiles, so hidden surfaces cost
  // nothing per pixel.
  bool CouldMatter(const PixelBox& box, std::array<double, 2> range, bool showing) const;
  void RefreshTiles();

  // The background where no surface is certain, then every pixel's class, written into `pixels`
  // (the whole frame's, row by row) and counted into `counts`, with the band's first and worst.
  void Finish(Verification& counts, std::vector<PixelClass>& pixels);
  Rgb8 ImageColour(int x, int y) const;
  std::uint32_t width() const { return image_->width; }
  std::uint32_t height() const { return image_->height; }

 private:
  std::size_t Index(int x, int y) const { return std::size_t(y - row0_) * image_->width + std::size_t(x); }
  const Image* image_;
  Rgb8 background_;
  bool reversed_ = false;
  int row0_ = 0, row1_ = 0;
  double clear_key_ = 1;
  // Depth keys are the depth for LESS and its negation for GREATER, so nearer is smaller. Per
  // pixel, the key of the nearest certain surface's farthest depth, kept as clear key - key
  // (0: none), so that a fresh frame is all zeros.
  std::vector<double> gap_;
  // Offers pairwise overlap exactly when, channel by channel, the largest low end is no more than
  // the smallest high end (Helly's theorem in one dimension): kept that way, the verdict does not
  // depend on the order of the offers. All zeros when nothing was offered.
  struct State {
    Rgb8 max_lo{0, 0, 0};
    Rgb8 hi_gap{0, 0, 0};       // 255 - the smallest high end
    std::uint8_t offers = 0;    // saturates at 2
    std::uint8_t closeness = 0; // 255 - the image colour's distance from the nearest offer
    std::uint8_t background_closeness = 0;  // the same for the background's colour
    std::uint8_t not_certain_line = 0;      // 1: some offer came from other than a certain line
  };
  std::vector<State> state_;
  friend struct FrameBuffers;
  static constexpr int kTile = 16;
  int tiles_x_ = 0;
  std::vector<double> tile_gap_;  // the smallest gap in each tile: its farthest bound
  std::vector<std::uint32_t> dirty_;
  std::vector<char> is_dirty_;
};

}  // namespace twinraster::verify
