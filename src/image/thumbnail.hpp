// A small copy of an image for a page of many: each thumbnail pixel stands for the block of source
// pixels it covers, as their mean (a picture) or as the most saturated of them (a diff or a
// verification map, whose marks are saturated on grey: one marked pixel still shows).
#pragma once

#include "image/image.hpp"

#include <cstdint>

namespace twinraster {

struct ThumbnailSize {
  std::uint32_t width = 0, height = 0;
};
// The size Thumbnail gives an image of width x height: a page can lay it out before it loads.
ThumbnailSize ThumbnailSizeFor(std::uint32_t width, std::uint32_t height, std::uint32_t max_side);

enum class ThumbnailFilter { kMean, kMostSaturated };

// At most `max_side` pixels on the longer side (an image already that small is copied as is).
Image Thumbnail(const Image& image, std::uint32_t max_side, ThumbnailFilter filter = ThumbnailFilter::kMean);

}  // namespace twinraster
