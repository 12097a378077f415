// The packets both rasterizers hand to the shared loop and the fragment stage: a pixel rectangle,
// a covered span of one row, the 16-row bands the rows are dealt out in and the binning into
// them, the colour planes of a Gouraud primitive whatever plane they are made of, and a colour as
// the framebuffer's word. It holds no device's arithmetic: each device's stages are in
// cpu/lavapipe/ and cpu/swiftshader/.
#pragma once

#include "chain/draw_list.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// Inclusive pixel rectangle; empty when x0 > x1 or y0 > y1.
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};

struct Span {
  int begin = 0, end = 0;  // covered pixels [begin, end) of one row; empty when begin >= end
};

// Rows [band * kBandRows, (band + 1) * kBandRows) belong to part band % parts.
constexpr int kBandRows = 16;

struct RowShare {
  unsigned parts = 1;
  unsigned part = 0;
};

// Which part owns the band of row y: bands are dealt out round-robin.
inline unsigned BandOwner(int y, unsigned parts) { return static_cast<unsigned>(y / kBandRows) % parts; }

// The bands a box touches, [first, last].
inline int FirstBand(const PixelRect& bounds) { return bounds.y0 / kBandRows; }
inline int LastBand(const PixelRect& bounds) { return bounds.y1 / kBandRows; }

// Bins a part's primitives while they are still in cache (most touch one band): bins[b] gets the
// index of each primitive whose box touches band b, in order.
template <class Primitives>
void BinPrimitives(const Primitives& primitives, std::vector<std::vector<std::uint32_t>>& bins) {
  for (std::size_t i = 0; i < primitives.size(); ++i) {
    for (int band = FirstBand(primitives[i].bounds); band <= LastBand(primitives[i].bounds); ++band) {
      bins[static_cast<std::size_t>(band)].push_back(static_cast<std::uint32_t>(i));
    }
  }
}

// Perspective-correct colour as two kinds of plane: one per channel through c·(1/w), and one
// through 1/w. `Plane` is how a plane is evaluated: lavapipe's DepthPlane or SwiftShader's
// AnchoredPlane, each with its PlaneDepth.
template <class Plane>
struct ColourPlanesOf {
  std::array<Plane, 3> colour_oow;  // r/w, g/w, b/w
  Plane oow;                        // 1/w
};

// The interpolated colour at pixel (px, py), before the conversion to UNORM8: one division, then
// a multiply per channel, as both devices do it.
template <class Plane>
glm::vec3 ColourAt(const ColourPlanesOf<Plane>& p, float px, float py) {
  const float w = 1.0f / PlaneDepth(p.oow, px, py);
  return glm::vec3(PlaneDepth(p.colour_oow[0], px, py) * w, PlaneDepth(p.colour_oow[1], px, py) * w,
                   PlaneDepth(p.colour_oow[2], px, py) * w);
}

// Rgb8 as the RGBA8 bytes (r, g, b, 255) in memory, viewed as one 32-bit word.
inline std::uint32_t PackRgba(Rgb8 colour) {
  return std::bit_cast<std::uint32_t>(std::array<std::uint8_t, 4>{colour.r, colour.g, colour.b, 255});
}

}  // namespace twinraster::cpu
