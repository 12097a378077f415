// Comparing images counts each differing pixel once, with its largest channel difference, and the
// image shifted one pixel right is the original one column over, its left column kept.
#include "image/image_compare.hpp"

#include "support/catch.hpp"

#include <cstdint>

using namespace twinraster;

namespace {

// Each pixel's red channel is its column, green its row: every pixel differs from its neighbours.
Image Gradient(std::uint32_t width, std::uint32_t height) {
  Image image(width, height);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = std::uint8_t(x), p[1] = std::uint8_t(y), p[2] = 7, p[3] = 255;
    }
  }
  return image;
}

}  // namespace

TEST_CASE("CompareImages counts the pixels that differ and the largest channel difference", "[image]") {
  const Image a = Gradient(5, 3);
  Image b = a;
  CHECK(CompareImages(a, b).Equal());
  b.pixel(1, 1)[2] = 10;  // 3 off
  b.pixel(4, 2)[0] = 0;   // 4 off
  b.pixel(4, 2)[1] = 0;   // 2 off, the same pixel
  const Comparison c = CompareImages(a, b);
  CHECK_FALSE(c.Equal());
  CHECK(c.differing_pixels == 2);
  CHECK(c.max_channel_difference == 4);
  CHECK_FALSE(CompareImages(a, Gradient(3, 5)).same_size);
}

TEST_CASE("ShiftedRight moves every row one pixel right and keeps the left column", "[image]") {
  const Image a = Gradient(6, 4);
  const Image s = ShiftedRight(a);
  REQUIRE(s.width == a.width);
  REQUIRE(s.height == a.height);
  for (std::uint32_t y = 0; y < a.height; ++y) {
    for (std::uint32_t x = 0; x < a.width; ++x) {
      INFO("pixel " << x << ", " << y);
      const std::uint8_t* want = a.pixel(x == 0 ? 0 : x - 1, y);
      const std::uint8_t* got = s.pixel(x, y);
      for (int k = 0; k < 4; ++k) CHECK(got[k] == want[k]);
    }
  }
  CHECK(CompareImages(a, s).differing_pixels == (a.width - 1) * a.height);
  const Image one = Gradient(1, 3);
  CHECK(CompareImages(one, ShiftedRight(one)).Equal());
}
