#include "verify/verify_map.hpp"

#include <bit>
#include <cstring>
#include <stdexcept>

namespace twinraster::verify {

Image VerificationMap(const Image& image, const Verification& v) {
  if (image.width != v.width || image.height != v.height) {
    throw std::invalid_argument("the verification is of a " + std::to_string(v.width) + " x " +
                                std::to_string(v.height) + " image, not this one");
  }
  Image map(image.width, image.height, Image::Uncleared{});  // every pixel is written below
  const std::size_t pixels = std::size_t{image.width} * image.height;
  // Every pixel in grey first, a whole pixel at a time so that the loop vectorizes; then the few
  // that are not certain, over it. A pixel's word holds R in its low byte on a little-endian
  // machine, which every machine twinraster builds for (x86-64, aarch64) is.
  static_assert(std::endian::native == std::endian::little);
  const std::uint8_t* in = image.rgba.data();
  std::uint8_t* grey_out = map.rgba.data();
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint32_t word = 0;
    std::memcpy(&word, in + 4 * i, 4);
    const std::uint32_t luma = (54 * (word & 255) + 183 * (word >> 8 & 255) + 19 * (word >> 16 & 255)) >> 8;
    const std::uint32_t grey = 128 + luma / 2;  // Rec. 709 weights, faded halfway to white
    const std::uint32_t out = grey | grey << 8 | grey << 16 | 0xff000000u;
    std::memcpy(grey_out + 4 * i, &out, 4);
  }
  static_assert(PixelClass::kCertain == PixelClass{0});
  for (std::size_t i = 0; i < pixels;) {
    std::uint64_t eight = 1;
    if (i + 8 <= pixels) std::memcpy(&eight, v.pixels.data() + i, 8);
    if (eight == 0) {  // eight certain pixels at once: the usual case
      i += 8;
      continue;
    }
    std::uint8_t* out = map.rgba.data() + 4 * i;
    const int grey = out[0];
    if (v.pixels[i] == PixelClass::kViolation) {
      out[0] = 255, out[1] = 0, out[2] = 0;
    } else if (v.pixels[i] == PixelClass::kUncertain) {  // amber (255, 176, 0), two thirds of the way from the grey
      out[0] = std::uint8_t((grey + 2 * 255) / 3), out[1] = std::uint8_t((grey + 2 * 176) / 3);
      out[2] = std::uint8_t(grey / 3);
    }
    ++i;
  }
  return map;
}

}  // namespace twinraster::verify
