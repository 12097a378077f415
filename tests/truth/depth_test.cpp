// Depth: clears, LESS and GREATER, equal depths, and z interpolated in window space.
#include "support/catch.hpp"
#include "truth_test_support.hpp"

using namespace twinraster;
using namespace twinraster::truthtest;

namespace {

constexpr Rgb8 kRed{255, 0, 0}, kBlue{0, 0, 255};

// The whole 8 x 8 canvas as two triangles; window depth z_left at x = 0 and z_right at x = 8, and
// clip w w_left and w_right there (w does not change the window depth).
std::vector<ClipTriangle> Quad(Rgb8 colour, double z_left, double z_right, double w_left = 1, double w_right = 1) {
  const glm::dvec4 tl = FromWindow(0, 0, z_left, 8, 8, w_left), tr = FromWindow(8, 0, z_right, 8, 8, w_right),
                   br = FromWindow(8, 8, z_right, 8, 8, w_right), bl = FromWindow(0, 8, z_left, 8, 8, w_left);
  return {{{tl, tr, br}, colour}, {{tl, br, bl}, colour}};
}

std::vector<ClipTriangle> Concat(std::vector<ClipTriangle> a, const std::vector<ClipTriangle>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

bool Is(const Image& image, int x, int y, Rgb8 c) {
  const std::uint8_t* p = image.pixel(std::uint32_t(x), std::uint32_t(y));
  return p[0] == c.r && p[1] == c.g && p[2] == c.b && p[3] == 255;
}

bool All(const Image& image, Rgb8 c) {
  for (int y = 0; y < int(image.height); ++y)
    for (int x = 0; x < int(image.width); ++x)
      if (!Is(image, x, y, c)) return false;
  return true;
}

}  // namespace

TEST_CASE("Truth depth: clears to the background, depth 1 (LESS) or 0 (GREATER)", "[truth][depth]") {
  CHECK(All(Render(MakeInput(8, 8, {})), kBackground));
  // A fragment at the clear value fails the test; one just inside passes.
  CHECK(All(Render(MakeInput(8, 8, Quad(kRed, 1.0, 1.0))), kBackground));
  CHECK(All(Render(MakeInput(8, 8, Quad(kRed, 0.999, 0.999))), kRed));
  CHECK(All(Render(MakeInput(8, 8, Quad(kRed, 0.0, 0.0), true)), kBackground));
  CHECK(All(Render(MakeInput(8, 8, Quad(kRed, 0.001, 0.001), true)), kRed));
}

TEST_CASE("Truth depth: LESS keeps the nearest, GREATER the farthest, equal keeps the first", "[truth][depth]") {
  const auto near = Quad(kBlue, 0.25, 0.25), far = Quad(kRed, 0.5, 0.5);
  CHECK(All(Render(MakeInput(8, 8, Concat(far, near))), kBlue));
  CHECK(All(Render(MakeInput(8, 8, Concat(near, far))), kBlue));
  CHECK(All(Render(MakeInput(8, 8, Concat(far, near), true)), kRed));
  CHECK(All(Render(MakeInput(8, 8, Concat(near, far), true)), kRed));
  const auto same = Quad(kBlue, 0.5, 0.5);
  CHECK(All(Render(MakeInput(8, 8, Concat(far, same))), kRed));
  CHECK(All(Render(MakeInput(8, 8, Concat(far, same), true)), kRed));
}

TEST_CASE("Truth depth: z is interpolated linearly in window space", "[truth][depth]") {
  // Red at depth 0.5, then blue from depth 0 at x = 0 to 1 at x = 8: at the centre of column px
  // blue is at (px + 0.5) / 8, nearer than red for px <= 3. The w at the sides differ (a
  // perspective view) and must not matter: window depth is affine in window x and y.
  for (const double w_right : {1.0, 4.0}) {
    const auto scene = Concat(Quad(kRed, 0.5, 0.5), Quad(kBlue, 0.0, 1.0, 1.0, w_right));
    const Image less = Render(MakeInput(8, 8, scene));
    const Image greater = Render(MakeInput(8, 8, scene, true));
    for (int y = 0; y < 8; ++y)
      for (int x = 0; x < 8; ++x) {
        INFO("pixel " << x << ", " << y << ", w_right " << w_right);
        CHECK(Is(less, x, y, x <= 3 ? kBlue : kRed));
        CHECK(Is(greater, x, y, x <= 3 ? kRed : kBlue));
      }
  }
}
