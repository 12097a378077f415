// The chapter demo's canvas: PutPixel on an image whose origin is the canvas centre, +y up, with
// JavaScript's truncation (`x | 0`) deciding the pixel.
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <utility>

namespace twinraster::book {

// JavaScript's `value | 0` (ToInt32): toward zero, then wrapped into 32 bits; NaN and infinities
// give 0. The demo draws with it, so that -0.5 and 0.5 both land on column 0 + Cw/2: the two halves
// of the canvas round in opposite directions.
std::int32_t TruncateToInt32(double value);

// An image the demo's PutPixel writes into. The demo keeps Cw/2 and Ch/2 as numbers; an odd size
// would put every pixel half a pixel off (its buffer offsets then land between pixels), so the
// book's rules need an even width and height (book_renderer.hpp checks the scene).
class DemoCanvas {
 public:
  // An even width and height, each at least 2; every pixel starts as `background`, opaque.
  // Throws std::invalid_argument for an odd or zero size.
  DemoCanvas(std::uint32_t width, std::uint32_t height, Rgb8 background);

  // Column Cw/2 + (x|0), row Ch/2 - (y|0) - 1 from the top; a pixel off the canvas is dropped, a
  // later pixel replaces an earlier one.
  void PutPixel(double x, double y, Rgb8 colour);

  const Image& image() const { return image_; }
  Image TakeImage() { return std::move(image_); }

 private:
  Image image_;
};

}  // namespace twinraster::book
