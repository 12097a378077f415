// The default PNG level's encoder against the others a user could pick, on one frame: libdeflate
// at levels 0, 1 and 6 (png_file.hpp) and stb_image_write (Debian's libstb), each timed (median)
// with its file's size. It checks no output: the PNG tests read every level back.
#pragma once

#include "image/image.hpp"

#include <cstddef>
#include <string>
#include <vector>

namespace twinraster::bench {

struct PngEncoding {
  std::string encoder;  // "runs (level 1)", "libdeflate 0", ..., "stb_image_write"
  double ms = 0;        // median
  std::size_t bytes = 0;
};

// Every encoder on `image`, `runs` times each, in turn.
std::vector<PngEncoding> ComparePngEncoders(const Image& image, int runs);

}  // namespace twinraster::bench
