#include "book/book_canvas.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace twinraster::book {

std::int32_t TruncateToInt32(double value) {
  if (!std::isfinite(value)) return 0;
  constexpr double kTwo32 = 4294967296.0;
  // fmod is exact, so the wrap is too: the result is trunc(value) modulo 2^32, as a signed number.
  double wrapped = std::fmod(std::trunc(value), kTwo32);
  if (wrapped < 0) wrapped += kTwo32;
  if (wrapped >= kTwo32 / 2) wrapped -= kTwo32;
  return static_cast<std::int32_t>(wrapped);
}

DemoCanvas::DemoCanvas(std::uint32_t width, std::uint32_t height, Rgb8 background) : image_(width, height) {
  if (width == 0 || height == 0 || width % 2 != 0 || height % 2 != 0) {
    throw std::invalid_argument("the demo's canvas needs an even width and height, not " + std::to_string(width) +
                                " x " + std::to_string(height));
  }
  for (std::size_t i = 0; i < image_.rgba.size(); i += 4) {
    image_.rgba[i] = background.r, image_.rgba[i + 1] = background.g, image_.rgba[i + 2] = background.b;
    image_.rgba[i + 3] = 255;
  }
}

void DemoCanvas::PutPixel(double x, double y, Rgb8 colour) {
  // In 64 bits: Cw/2 + (x|0) can pass 2^31 when x|0 is near its largest.
  const std::int64_t column = std::int64_t{image_.width / 2} + TruncateToInt32(x);
  const std::int64_t row = std::int64_t{image_.height / 2} - TruncateToInt32(y) - 1;
  if (column < 0 || column >= std::int64_t{image_.width} || row < 0 || row >= std::int64_t{image_.height}) return;
  std::uint8_t* p = image_.pixel(static_cast<std::uint32_t>(column), static_cast<std::uint32_t>(row));
  p[0] = colour.r, p[1] = colour.g, p[2] = colour.b, p[3] = 255;
}

}  // namespace twinraster::book
