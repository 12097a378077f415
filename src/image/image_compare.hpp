// Compares two images pixel by pixel: how many pixels differ, by how much at most, and a diff
// image that shows where; and makes the image one pixel off that the verifier's tests and bench
// judge as failing. It does not judge whether a difference is allowed (verify/ does).
#pragma once

#include "image/image.hpp"

#include <cstdint>
#include <optional>

namespace twinraster {

struct Comparison {
  bool same_size = true;
  std::uint64_t differing_pixels = 0;
  int max_channel_difference = 0;  // over R, G, B, A
  bool Equal() const { return same_size && differing_pixels == 0; }
};

Comparison CompareImages(const Image& a, const Image& b);
// One row of two images of one size, `width` RGBA pixels each, added to `c`: for a caller that
// reads the images a row at a time (compare) rather than holding them.
void CompareRow(const std::uint8_t* a, const std::uint8_t* b, std::uint32_t width, Comparison& c);
// One row of the diff image (below) into `out`, `width` RGBA pixels.
void DiffRow(const std::uint8_t* a, const std::uint8_t* b, std::uint32_t width, std::uint8_t* out);

// Differing pixels in red over a faded grey copy of `a`; images must have the same size.
Image DiffImage(const Image& a, const Image& b);

// The image moved one pixel right, the left column keeping its colour: what a device drawing one
// pixel off would write.
Image ShiftedRight(const Image& image);

}  // namespace twinraster
