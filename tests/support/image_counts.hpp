// Counting pixels in an Image, for tests that check a picture is not blank or count what it painted.
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"  // Rgb8

#include <cstddef>
#include <cstdint>
#include <set>

namespace twinraster::test {

// Pixels whose colour (alpha aside) is not `colour`: what was painted over a background.
inline std::size_t CountNotColour(const Image& image, Rgb8 colour) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    n += image.rgba[i] != colour.r || image.rgba[i + 1] != colour.g || image.rgba[i + 2] != colour.b;
  }
  return n;
}

// The number of distinct colours (alpha aside): a lit or interpolated surface has many, a flat one few.
inline std::size_t DistinctColours(const Image& image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    colours.insert(std::uint32_t{image.rgba[i]} | std::uint32_t{image.rgba[i + 1]} << 8 |
                   std::uint32_t{image.rgba[i + 2]} << 16);
  }
  return colours.size();
}

}  // namespace twinraster::test
