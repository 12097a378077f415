// A small copy of an image for a page of many: each thumbnail pixel the mean of the source
// pixels it covers, so that a single differing pixel still shows as a tint.
#pragma once

#include "image/image.hpp"

#include <cstdint>

namespace twinraster {

struct ThumbnailSize {
  std::uint32_t width = 0, height = 0;
};
// The size Thumbnail gives an image of width x height: a page can lay it out before it loads.
ThumbnailSize ThumbnailSizeFor(std::uint32_t width, std::uint32_t height, std::uint32_t max_side);

// At most `max_side` pixels on the longer side (an image already that small is copied as is).
Image Thumbnail(const Image& image, std::uint32_t max_side);

}  // namespace twinraster
