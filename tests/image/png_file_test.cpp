// PNG output is lossless at every level: encoded images decode (with stb_image, an independent
// decoder) to the same pixels, and higher levels give smaller files.
#include "image/png_file.hpp"
#include "support/test_support.hpp"

#include "support/catch.hpp"

#include <random>

using namespace twinraster;

namespace {

// Flat triangles on a background, like a render, plus a band of noise that no filter predicts.
Image TestImage(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
  Image image(width, height);
  std::mt19937 random(seed);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      if (y % 7 == 3) {
        for (int c = 0; c < 4; ++c) p[c] = static_cast<std::uint8_t>(random());
      } else {
        const bool inside = x * height < y * width;
        p[0] = inside ? 255 : 10, p[1] = static_cast<std::uint8_t>(x), p[2] = static_cast<std::uint8_t>(y), p[3] = 255;
      }
    }
  }
  return image;
}

}  // namespace

TEST_CASE("PNG round trip: every level decodes to the same pixels", "[png]") {
  const test::TempDir dir;
  for (const auto& [width, height] : {std::pair{1u, 1u}, {3u, 5u}, {640u, 480u}, {1920u, 1080u}}) {
    const Image image = TestImage(width, height, width + height);
    for (const int level : {0, kPngFastest, 6, kPngSmallest}) {
      INFO(width << "x" << height << " level " << level);
      WritePng(dir / "round.png", image, level);
      const Image back = ReadPng(dir / "round.png");
      REQUIRE(back.width == image.width);
      REQUIRE(back.height == image.height);
      REQUIRE(back.rgba == image.rgba);
    }
  }
}

TEST_CASE("PNG levels: 0 stores, higher levels are no larger", "[png]") {
  const Image image = TestImage(640, 480, 7);
  const std::size_t stored = EncodePng(image, 0).size();
  const std::size_t fastest = EncodePng(image, kPngFastest).size();
  const std::size_t smallest = EncodePng(image, kPngSmallest).size();
  REQUIRE(stored > image.rgba.size());  // the filtered scanlines, uncompressed, plus headers
  REQUIRE(fastest < stored);
  REQUIRE(smallest <= fastest);
}

TEST_CASE("PNG: a level outside 0..12 and an empty image are refused", "[png]") {
  REQUIRE_THROWS_AS(EncodePng(TestImage(2, 2, 1), -1), std::invalid_argument);
  REQUIRE_THROWS_AS(EncodePng(TestImage(2, 2, 1), 13), std::invalid_argument);
  REQUIRE_THROWS_AS(EncodePng(Image()), std::invalid_argument);
}
