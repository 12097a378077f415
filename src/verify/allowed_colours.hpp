// What one surface (or the background) may write at a pixel: an 8-bit range per channel, because
// UNORM conversion may round either way and light and interpolation run in float.
#pragma once

#include "scene/scene.hpp"

#include <algorithm>
#include <cstdint>

namespace twinraster::verify {

struct ColourRange {
  Rgb8 lo, hi;

  static ColourRange Exactly(Rgb8 c) { return {c, c}; }
  bool Contains(Rgb8 c) const {
    return c.r >= lo.r && c.r <= hi.r && c.g >= lo.g && c.g <= hi.g && c.b >= lo.b && c.b <= hi.b;
  }
  // How far `c` lies outside the range: the largest channel's distance, 0 inside.
  int Distance(Rgb8 c) const {
    const auto d = [](int v, int l, int h) { return v < l ? l - v : v > h ? v - h : 0; };
    return std::max({d(c.r, lo.r, hi.r), d(c.g, lo.g, hi.g), d(c.b, lo.b, hi.b)});
  }
  friend bool operator==(const ColourRange&, const ColourRange&) = default;
};

}  // namespace twinraster::verify
