#include "image/image_compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace twinraster {

Comparison CompareImages(const Image& a, const Image& b) {
  Comparison c;
  if (a.width != b.width || a.height != b.height) {
    c.same_size = false;
    return c;
  }
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    int worst = 0;
    for (std::size_t k = 0; k < 4; ++k) worst = std::max(worst, std::abs(int(a.rgba[i + k]) - int(b.rgba[i + k])));
    if (worst > 0) ++c.differing_pixels;
    c.max_channel_difference = std::max(c.max_channel_difference, worst);
  }
  return c;
}

Image DiffImage(const Image& a, const Image& b) {
  Image diff(a.width, a.height);
  for (std::size_t i = 0; i < a.rgba.size(); i += 4) {
    const bool differs = !std::equal(&a.rgba[i], &a.rgba[i] + 4, &b.rgba[i]);
    // Faded luminance keeps the picture recognisable without competing with the red.
    const int luminance = (a.rgba[i] * 3 + a.rgba[i + 1] * 6 + a.rgba[i + 2]) / 10;
    const auto faded = static_cast<std::uint8_t>(192 + luminance / 4);
    diff.rgba[i + 0] = differs ? 255 : faded;
    diff.rgba[i + 1] = differs ? 0 : faded;
    diff.rgba[i + 2] = differs ? 0 : faded;
    diff.rgba[i + 3] = 255;
  }
  return diff;
}

Image ShiftedRight(const Image& image) {
  Image out = image;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    if (image.width > 1) std::memmove(out.pixel(1, y), image.pixel(0, y), 4 * std::size_t{image.width - 1});
  }
  return out;
}

}  // namespace twinraster
