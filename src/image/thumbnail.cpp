#include "image/thumbnail.hpp"

#include <algorithm>

namespace twinraster {

ThumbnailSize ThumbnailSizeFor(std::uint32_t width, std::uint32_t height, std::uint32_t max_side) {
  const std::uint32_t longer = std::max(width, height);
  if (longer <= max_side || max_side == 0) return {width, height};
  const auto scaled = [&](std::uint32_t side) {
    return std::max<std::uint32_t>(1, static_cast<std::uint32_t>(std::uint64_t{side} * max_side / longer));
  };
  return {scaled(width), scaled(height)};
}

Image Thumbnail(const Image& image, std::uint32_t max_side, ThumbnailFilter filter) {
  const ThumbnailSize size = ThumbnailSizeFor(image.width, image.height, max_side);
  if (size.width == image.width && size.height == image.height) return image;
  Image thumb(size.width, size.height);
  // Source rows [y0, y1) and columns [x0, x1) fall on thumbnail pixel (tx, ty): a box filter.
  for (std::uint32_t ty = 0; ty < thumb.height; ++ty) {
    const std::uint32_t y0 = static_cast<std::uint32_t>(std::uint64_t{ty} * image.height / thumb.height);
    const std::uint32_t y1 = static_cast<std::uint32_t>(std::uint64_t{ty + 1} * image.height / thumb.height);
    for (std::uint32_t tx = 0; tx < thumb.width; ++tx) {
      const std::uint32_t x0 = static_cast<std::uint32_t>(std::uint64_t{tx} * image.width / thumb.width);
      const std::uint32_t x1 = static_cast<std::uint32_t>(std::uint64_t{tx + 1} * image.width / thumb.width);
      std::uint32_t total[4] = {0, 0, 0, 0};
      const std::uint8_t* most_saturated = image.pixel(x0, y0);
      int saturation = -1;
      for (std::uint32_t y = y0; y < y1; ++y) {
        for (std::uint32_t x = x0; x < x1; ++x) {
          const std::uint8_t* p = image.pixel(x, y);
          for (int c = 0; c < 4; ++c) total[c] += p[c];
          const int s = std::max({p[0], p[1], p[2]}) - std::min({p[0], p[1], p[2]});
          if (s > saturation) saturation = s, most_saturated = p;
        }
      }
      const std::uint32_t count = (y1 - y0) * (x1 - x0);
      std::uint8_t* out = thumb.pixel(tx, ty);
      for (int c = 0; c < 4; ++c) {
        out[c] = filter == ThumbnailFilter::kMean ? static_cast<std::uint8_t>((total[c] + count / 2) / count)
                                                  : most_saturated[c];
      }
    }
  }
  return thumb;
}

}  // namespace twinraster
