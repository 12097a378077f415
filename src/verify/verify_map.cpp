#include "verify/verify_map.hpp"

#include <stdexcept>

namespace twinraster::verify {

Image VerificationMap(const Image& image, const Verification& v) {
  if (image.width != v.width || image.height != v.height) {
    throw std::invalid_argument("the verification is of a " + std::to_string(v.width) + " x " +
                                std::to_string(v.height) + " image, not this one");
  }
  Image map(image.width, image.height);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* in = image.pixel(x, y);
      std::uint8_t* out = map.pixel(x, y);
      const int luma = (54 * in[0] + 183 * in[1] + 19 * in[2]) >> 8;  // Rec. 709 weights
      const int grey = 128 + luma / 2;
      switch (v.pixels[std::size_t{y} * image.width + x]) {
        case PixelClass::kCertain: out[0] = out[1] = out[2] = std::uint8_t(grey); break;
        case PixelClass::kUncertain:  // amber (255, 176, 0), two thirds of the way from the grey
          out[0] = std::uint8_t((grey + 2 * 255) / 3), out[1] = std::uint8_t((grey + 2 * 176) / 3);
          out[2] = std::uint8_t(grey / 3);
          break;
        case PixelClass::kViolation: out[0] = 255, out[1] = 0, out[2] = 0; break;
      }
      out[3] = 255;
    }
  }
  return map;
}

}  // namespace twinraster::verify
