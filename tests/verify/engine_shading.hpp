// What the coverage tests draw as an engine's own shading over the twin's image: the covered pixels
// recoloured (constant, gradient, noise, darker, brighter), never in the clear colour, and the
// background cleared to it. It judges nothing: the tests pass these images to run::JudgeCoverage.
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"  // Rgb8

#include <algorithm>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

namespace twinraster::test {

inline bool Is(const std::uint8_t* p, Rgb8 c) { return p[0] == c.r && p[1] == c.g && p[2] == c.b; }

// An engine's shading: each covered pixel (not `from`, the twin's background) gets a colour of its
// own, never `clear` (an engine that follows docs/verify.md's advice: a clear colour its shading
// cannot produce); background pixels become `clear`.
enum class Shade { kConstant, kGradient, kNoise, kDarker, kBrighter };
inline const std::vector<std::pair<Shade, const char*>> kShades = {{Shade::kConstant, "constant"},
                                                                   {Shade::kGradient, "gradient"},
                                                                   {Shade::kNoise, "noise"},
                                                                   {Shade::kDarker, "darkened"},
                                                                   {Shade::kBrighter, "brightened"}};

inline Image Recolour(const Image& twin, Rgb8 from, Rgb8 clear, Shade shade, std::uint32_t seed = 1) {
  Image out = twin;
  std::mt19937 random(seed);
  std::uniform_int_distribution<int> byte(0, 255);
  for (std::uint32_t y = 0; y < twin.height; ++y) {
    for (std::uint32_t x = 0; x < twin.width; ++x) {
      std::uint8_t* p = out.pixel(x, y);
      if (Is(p, from)) {
        p[0] = clear.r, p[1] = clear.g, p[2] = clear.b;
        continue;
      }
      switch (shade) {
        case Shade::kConstant: p[0] = 90, p[1] = 140, p[2] = 200; break;
        case Shade::kGradient:
          p[0] = std::uint8_t(x * 255 / twin.width), p[1] = std::uint8_t(y * 255 / twin.height), p[2] = 128;
          break;
        case Shade::kNoise:
          p[0] = std::uint8_t(byte(random)), p[1] = std::uint8_t(byte(random)), p[2] = std::uint8_t(byte(random));
          break;
        case Shade::kDarker:
        case Shade::kBrighter:
          for (int c = 0; c < 3; ++c) p[c] = std::uint8_t(std::min(255, p[c] * (shade == Shade::kDarker ? 2 : 7) / 4));
          break;
      }
      if (Is(p, clear)) p[0] ^= 1;  // the one colour this engine's shading never gives
    }
  }
  return out;
}

}  // namespace twinraster::test
