#include "image/image_compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace twinraster {

void CompareRow(const std::uint8_t* a, const std::uint8_t* b, std::uint32_t width, Comparison& c) {
  for (std::size_t i = 0; i < std::size_t{width} * 4; i += 4) {
    int worst = 0;
    for (std::size_t k = 0; k < 4; ++k) worst = std::max(worst, std::abs(int(a[i + k]) - int(b[i + k])));
    if (worst > 0) ++c.differing_pixels;
    c.max_channel_difference = std::max(c.max_channel_difference, worst);
  }
}

void DiffRow(const std::uint8_t* a, const std::uint8_t* b, std::uint32_t width, std::uint8_t* out) {
  for (std::size_t i = 0; i < std::size_t{width} * 4; i += 4) {
    const bool differs = !std::equal(a + i, a + i + 4, b + i);
    // Faded luminance keeps the picture recognisable without competing with the red.
    const int luminance = (a[i] * 3 + a[i + 1] * 6 + a[i + 2]) / 10;
    const auto faded = static_cast<std::uint8_t>(192 + luminance / 4);
    out[i + 0] = differs ? 255 : faded;
    out[i + 1] = differs ? 0 : faded;
    out[i + 2] = differs ? 0 : faded;
    out[i + 3] = 255;
  }
}

Comparison CompareImages(const Image& a, const Image& b) {
  Comparison c;
  if (a.width != b.width || a.height != b.height) {
    c.same_size = false;
    return c;
  }
  for (std::uint32_t y = 0; y < a.height; ++y) CompareRow(a.pixel(0, y), b.pixel(0, y), a.width, c);
  return c;
}

Image DiffImage(const Image& a, const Image& b) {
  Image diff(a.width, a.height);
  for (std::uint32_t y = 0; y < a.height; ++y) DiffRow(a.pixel(0, y), b.pixel(0, y), a.width, diff.pixel(0, y));
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
