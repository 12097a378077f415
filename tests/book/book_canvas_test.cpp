// The demo's canvas: JavaScript's `| 0`, and where PutPixel puts a canvas point.
#include "book/book_canvas.hpp"

#include "support/catch.hpp"
#include "support/image_counts.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

using namespace twinraster;
using namespace twinraster::book;

namespace {

constexpr Rgb8 kWhite{255, 255, 255}, kRed{255, 0, 0};

bool IsRed(const Image& image, std::uint32_t column, std::uint32_t row) {
  const std::uint8_t* p = image.pixel(column, row);
  return p[0] == 255 && p[1] == 0 && p[2] == 0 && p[3] == 255;
}

}  // namespace

TEST_CASE("TruncateToInt32 is JavaScript's | 0: toward zero, wrapped into 32 bits, 0 for NaN and infinities",
          "[book][canvas]") {
  // Each value checked against node: (2.9)|0, (-2.9)|0, (-0.5)|0, (2**31)|0, (2**32+5)|0, (-(2**31)-1)|0.
  REQUIRE(TruncateToInt32(2.9) == 2);
  REQUIRE(TruncateToInt32(-2.9) == -2);
  REQUIRE(TruncateToInt32(-0.5) == 0);
  REQUIRE(TruncateToInt32(2147483648.0) == -2147483648);
  REQUIRE(TruncateToInt32(4294967301.0) == 5);
  REQUIRE(TruncateToInt32(-2147483649.0) == 2147483647);
  REQUIRE(TruncateToInt32(std::numeric_limits<double>::quiet_NaN()) == 0);
  REQUIRE(TruncateToInt32(-std::numeric_limits<double>::infinity()) == 0);
}

TEST_CASE("PutPixel: column Cw/2 + (x|0), row Ch/2 - (y|0) - 1, off-canvas pixels dropped", "[book][canvas]") {
  DemoCanvas canvas(600, 600, kWhite);
  canvas.PutPixel(0, 0, kRed);
  REQUIRE(IsRed(canvas.image(), 300, 299));
  // -0.9 truncates to 0 as 0.9 does: the pixel left of and below the origin is not reached.
  canvas.PutPixel(-0.9, -0.9, kRed);
  REQUIRE(test::CountNotColour(canvas.image(), kWhite) == 1);
  canvas.PutPixel(-1, -1, kRed);
  REQUIRE(IsRed(canvas.image(), 299, 300));
  // The corners: (299.9, 299.9) -> column 599, row 0; x = -300.5 truncates to -300 -> column 0;
  // y = -300 -> row 599.
  canvas.PutPixel(299.9, 299.9, kRed);
  REQUIRE(IsRed(canvas.image(), 599, 0));
  canvas.PutPixel(-300.5, -300, kRed);
  REQUIRE(IsRed(canvas.image(), 0, 599));
  REQUIRE(test::CountNotColour(canvas.image(), kWhite) == 4);
  // Just off: column 600, row -1 (y = 300), row 600 (y = -301), column -1 (x = -301).
  canvas.PutPixel(300, 0, kRed);
  canvas.PutPixel(0, 300, kRed);
  canvas.PutPixel(0, -301, kRed);
  canvas.PutPixel(-301, 0, kRed);
  REQUIRE(test::CountNotColour(canvas.image(), kWhite) == 4);
}

TEST_CASE("The demo's canvas starts as the background, opaque, and needs an even size", "[book][canvas]") {
  const DemoCanvas canvas(4, 2, Rgb8{1, 2, 3});
  for (std::size_t i = 0; i < canvas.image().rgba.size(); i += 4) {
    REQUIRE(canvas.image().rgba[i] == 1);
    REQUIRE(canvas.image().rgba[i + 3] == 255);
  }
  REQUIRE_THROWS_AS(DemoCanvas(601, 600, kWhite), std::invalid_argument);
  REQUIRE_THROWS_AS(DemoCanvas(600, 3, kWhite), std::invalid_argument);
  REQUIRE_THROWS_AS(DemoCanvas(0, 600, kWhite), std::invalid_argument);
}
