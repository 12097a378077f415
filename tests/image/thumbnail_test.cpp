// Thumbnails on their own: pictures are averaged, and a diff keeps a single marked pixel.
#include "image/thumbnail.hpp"

#include "support/catch.hpp"

#include <cstddef>
#include <cstdint>

using namespace twinraster;

TEST_CASE("Thumbnail: pictures are averaged, one marked pixel of a diff survives", "[image]") {
  Image diff(600, 400);
  for (std::size_t i = 0; i < diff.rgba.size(); i += 4)
    diff.rgba[i] = diff.rgba[i + 1] = diff.rgba[i + 2] = 220, diff.rgba[i + 3] = 255;
  std::uint8_t* marked = diff.pixel(301, 117);
  marked[0] = 255, marked[1] = 0, marked[2] = 0;
  const Image mean = Thumbnail(diff, 96), kept = Thumbnail(diff, 96, ThumbnailFilter::kMostSaturated);
  REQUIRE(mean.width == 96);
  REQUIRE(mean.height == 64);
  CHECK(ThumbnailSizeFor(600, 400, 96).width == 96);
  CHECK(ThumbnailSizeFor(600, 400, 96).height == 64);
  std::size_t red_mean = 0, red_kept = 0;
  for (std::size_t i = 0; i < mean.rgba.size(); i += 4) {
    red_mean += mean.rgba[i] == 255 && mean.rgba[i + 1] == 0;
    red_kept += kept.rgba[i] == 255 && kept.rgba[i + 1] == 0;
  }
  CHECK(red_mean == 0);
  CHECK(red_kept == 1);
  const Image small(50, 20);
  CHECK(Thumbnail(small, 96).width == 50);
}
