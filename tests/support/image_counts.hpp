// Counting pixels in an Image, for tests that check a picture is not blank or count what it painted.
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"  // Rgb8

#include <cstddef>

namespace twinraster::test {

// Pixels whose colour (alpha aside) is not `colour`: what was painted over a background.
inline std::size_t CountNotColour(const Image& image, Rgb8 colour) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    n += image.rgba[i] != colour.r || image.rgba[i + 1] != colour.g || image.rgba[i + 2] != colour.b;
  }
  return n;
}

}  // namespace twinraster::test
