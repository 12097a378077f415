// The verifier on hand-made cases: what is certain, uncertain and a violation, and bad input.
#include "verify/verifier.hpp"

#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "run_report/verify_report.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "verify/verify_map.hpp"

using namespace twinraster;

namespace {

// One square of two triangles on a 64 x 48 canvas, seen from 2 units away.
const char* kSquare = R"({
  "canvas": {"width": 64, "height": 48, "background": [255, 255, 255]},
  "viewport": {"width": 1.3333333333333333, "height": 1, "distance": 1},
  "camera": {"position": [0, 0, 0]},
  "models": {"square": {"vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
                         "triangles": [[0, 1, 2, [200, 30, 30]], [0, 2, 3, [200, 30, 30]]]}},
  "instances": [{"model": "square", "transform": {"translation": [0, 0, 4]}}]
})";

struct Case {
  Scene scene;
  DrawList list;
  Image image;
};

Case Square() {
  Case c{ParseScene(kSquare, "square.json"), {}, {}};
  c.list = BuildDrawList(c.scene);
  c.image = cpu::RenderOnCpu(c.list);
  return c;
}

void Paint(Image& image, std::uint32_t x, std::uint32_t y, Rgb8 c) {
  std::uint8_t* p = image.pixel(x, y);
  p[0] = c.r, p[1] = c.g, p[2] = c.b;
}

}  // namespace

TEST_CASE("verify: the twin's image of a square passes, its inside and outside certain, its edge alone uncertain",
          "[verify]") {
  const Case c = Square();
  const verify::Verification v = verify::VerifyImage(c.scene, c.list, c.image, {.subpixel_bits = 8});
  CHECK(v.NoViolations());
  CHECK(v.violations == 0);
  CHECK(v.certain + v.uncertain == 64u * 48u);
  // The square spans window x 20..44, y 12..36 (48 px per unit of the viewport, z = 4): its edges
  // lie on pixel boundaries, half a pixel from every centre, so at 8 bits nothing is uncertain.
  CHECK(v.uncertain == 0);
  CHECK(v.covered == 24u * 24u);
  CHECK(v.pixels[std::size_t(24) * 64 + 32] == verify::PixelClass::kCertain);
}

TEST_CASE(
    "verify: a wrong colour inside the square, or a grey pixel outside it, is a violation named with what is allowed",
    "[verify]") {
  Case c = Square();
  Paint(c.image, 30, 20, {0, 0, 255});
  Paint(c.image, 5, 5, {240, 240, 240});
  const verify::Verification v = verify::VerifyImage(c.scene, c.list, c.image, {.subpixel_bits = 8});
  CHECK_FALSE(v.NoViolations());
  CHECK(v.violations == 2);
  REQUIRE(v.first);
  CHECK(v.first->x == 5);
  CHECK(v.first->y == 5);
  REQUIRE(v.first->allowed.size() == 1);
  CHECK(v.first->allowed[0] == verify::ColourRange::Exactly({255, 255, 255}));
  REQUIRE(v.worst);
  CHECK(v.worst->x == 30);
  CHECK(v.worst->y == 20);
  CHECK(v.worst->distance == 225);  // blue 255 against 30
  CHECK(v.worst->allowed == std::vector<verify::ColourRange>{verify::ColourRange::Exactly({200, 30, 30})});
  const Image map = verify::VerificationMap(c.image, v);
  CHECK(map.pixel(30, 20)[0] == 255);
  CHECK(map.pixel(30, 20)[1] == 0);
  CHECK(map.pixel(31, 20)[0] == map.pixel(31, 20)[1]);  // certain: grey
  CHECK_THAT(run_report::VerificationText(v), HasSubstring("fails: 2 pixels are not allowed; worst at (30, 20)"));
}

TEST_CASE("verify: with an edge through pixel centres, both answers are allowed there and those pixels are uncertain",
          "[verify]") {
  // Moved a quarter of a pixel right (1/48 of a unit at z = 4 is 48 / 4 / 48 px): the side edges
  // pass at x = 20.25 and 44.25, a quarter pixel from centres. At 4 subpixel bits a vertex may
  // move 1/16 of a pixel, not enough to reach a centre; at 1 bit, half a pixel, it may.
  std::string text = kSquare;
  text.replace(text.find("[0, 0, 4]"), 9, "[0.020833333333333332, 0, 4]");
  Case c{ParseScene(text, "square.json"), {}, {}};
  c.list = BuildDrawList(c.scene);
  c.image = cpu::RenderOnCpu(c.list);
  const verify::Verification sharp = verify::VerifyImage(c.scene, c.list, c.image, {.subpixel_bits = 4});
  const verify::Verification loose = verify::VerifyImage(c.scene, c.list, c.image, {.subpixel_bits = 1});
  CHECK(sharp.NoViolations());
  CHECK(loose.NoViolations());
  CHECK(loose.uncertain >= 2u * 24u);  // a column at each side edge
  CHECK(sharp.uncertain < loose.uncertain);
}

TEST_CASE("verify: an image of the wrong size is refused", "[verify]") {
  const Case c = Square();
  const Image small(32, 24);
  CHECK_THROWS_WITH(verify::VerifyImage(c.scene, c.list, small), HasSubstring("the image is 32 x 24"));
}
