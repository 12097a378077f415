#include "files/png_scanlines.hpp"

#include <cstring>

namespace twinraster::files::png_scanlines {

// Rendered images are mostly flat runs and straight edges, where Up leaves long runs of zeros for
// deflate; trying all five filters per row, as stb_image_write does, costs more than it saves at
// fast levels.
void FilterRows(const Image& image, std::uint32_t first, std::uint32_t last, std::uint8_t* out) {
  const std::size_t stride = std::size_t{image.width} * 4;
  for (std::uint32_t y = first; y < last; ++y, out += stride + 1) {
    const std::uint8_t* row = image.rgba.data() + stride * y;
    if (y == 0) {
      out[0] = 0;  // None: the first row has nothing above it
      std::memcpy(out + 1, row, stride);
      continue;
    }
    out[0] = 2;  // Up
    const std::uint8_t* above = row - stride;
    for (std::size_t i = 0; i < stride; ++i) out[1 + i] = static_cast<std::uint8_t>(row[i] - above[i]);
  }
}

}  // namespace twinraster::files::png_scanlines
