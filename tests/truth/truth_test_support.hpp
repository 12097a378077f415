// Hand-made inputs for the truth's tests: triangles given by window positions (turned into clip
// positions the viewport transform maps back exactly) and the pixels they cover.
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "truth/truth_renderer.hpp"

#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <set>
#include <utility>
#include <vector>

namespace twinraster::truthtest {

constexpr Rgb8 kBackground{10, 20, 30};

struct ClipTriangle {
  std::array<glm::dvec4, 3> v;
  Rgb8 colour{200, 100, 50};
};

// Clip position of window position (x, y) at depth z, scaled by w > 0 (w changes nothing on
// screen). Exact for power-of-two sizes and window coordinates with few fraction bits.
inline glm::dvec4 FromWindow(double x, double y, double z, std::uint32_t width, std::uint32_t height, double w = 1.0) {
  return {w * (2.0 * x / width - 1.0), w * (2.0 * y / height - 1.0), w * z, w};
}

// One draw of one mesh holding every triangle's own three vertices, with the truth's clip positions.
struct TruthInput {
  DrawList list;
  truth::ExactClipPositions clip;
};

inline TruthInput MakeInput(std::uint32_t width, std::uint32_t height, const std::vector<ClipTriangle>& triangles,
                            bool reversed_z = false) {
  TruthInput in;
  in.list.width = width;
  in.list.height = height;
  in.list.background = kBackground;
  in.list.reversed_z = reversed_z;
  DrawMesh mesh;
  std::vector<glm::dvec4> clip;
  for (const ClipTriangle& t : triangles) {
    const auto first = static_cast<std::uint32_t>(clip.size());
    for (const glm::dvec4& v : t.v) {
      clip.push_back(v);
      mesh.positions.emplace_back(0.0f);  // unused by the truth; only the count matters
    }
    mesh.triangles.push_back({first, first + 1, first + 2});
    mesh.colours.push_back(t.colour);
  }
  in.list.meshes.push_back(std::move(mesh));
  in.list.draws.push_back(DrawCall{});
  in.clip.push_back(std::move(clip));
  return in;
}

inline Image Render(const TruthInput& in) { return truth::RenderTruth(in.list, in.clip); }

inline bool IsBackground(const Image& image, std::uint32_t x, std::uint32_t y, Rgb8 background = kBackground) {
  const std::uint8_t* p = image.pixel(x, y);
  return p[0] == background.r && p[1] == background.g && p[2] == background.b;
}

using PixelSet = std::set<std::pair<int, int>>;  // (px, py)

// The pixels that are not background.
inline PixelSet CoveredPixels(const Image& image) {
  PixelSet covered;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x)
      if (!IsBackground(image, x, y)) covered.insert({static_cast<int>(x), static_cast<int>(y)});
  return covered;
}

// The pixels one triangle covers, drawn alone.
inline PixelSet CoveredBy(std::uint32_t width, std::uint32_t height, const ClipTriangle& triangle) {
  return CoveredPixels(Render(MakeInput(width, height, {triangle})));
}

// How many of `triangles`, each drawn alone, cover each pixel (index y * width + x).
inline std::vector<int> CoverageCounts(std::uint32_t width, std::uint32_t height,
                                       const std::vector<ClipTriangle>& triangles) {
  std::vector<int> counts(std::size_t{width} * height, 0);
  for (const ClipTriangle& t : triangles)
    for (const auto& [x, y] : CoveredBy(width, height, t)) ++counts[std::size_t(y) * width + std::size_t(x)];
  return counts;
}

// Pixels (px, py) in [x0, x1] x [y0, y1] with keep(px, py).
template <class Keep>
PixelSet PixelsWhere(int x0, int x1, int y0, int y1, Keep keep) {
  PixelSet pixels;
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x)
      if (keep(x, y)) pixels.insert({x, y});
  return pixels;
}

}  // namespace twinraster::truthtest
