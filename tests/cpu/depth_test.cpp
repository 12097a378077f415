// Stage 6 and 7: the depth plane, its evaluation, and the LESS depth test.
#include "cpu/fragment_ops.hpp"
#include "cpu/lavapipe/plane.hpp"
#include "cpu/lavapipe/setup.hpp"
#include "support/catch.hpp"

#include <cmath>

using namespace twinraster::cpu;

namespace {

Framebuffer Cleared(std::uint32_t w, std::uint32_t h, std::uint32_t colour, DepthCompare op = DepthCompare::kLess) {
  Framebuffer fb(w, h, op);
  ClearRows(fb, 0, static_cast<int>(h), colour);
  return fb;
}

}  // namespace

TEST_CASE("depth plane through three window-space vertices", "[cpu][depth]") {
  // z = 0.25 + (x - 0.5) / 16 + (y - 0.5) / 32. The snapped area is negative, so setup swaps
  // vertices 1 and 2 before building the plane: with v0 = (0.5, 0.5), v1 = (0.5, 8.5),
  // v2 = (8.5, 0.5): e = 0, f = -64, ooa = 1/64, dzdx = -(0.5)(-0.125) = 0.0625,
  // dzdy = -(-0.25)(0.125) = 0.03125, a0 = 0.25 - 0 = 0.25.
  TriangleSetup t;
  REQUIRE(SetUpTriangle({0.5f, 0.5f, 0.25f}, {8.5f, 0.5f, 0.75f}, {0.5f, 8.5f, 0.5f}, PixelRect{0, 0, 15, 15}, t));
  CHECK(t.swapped);
  CHECK(t.depth.a0 == 0.25f);
  CHECK(t.depth.dzdx == 0.0625f);
  CHECK(t.depth.dzdy == 0.03125f);
  CHECK(DepthAt(t.depth, 4, 2) == 0.5625f);  // 0.25 + 4/16 + 2/32
  CHECK(DepthAt(t.depth, 0, 0) == 0.25f);
}

TEST_CASE("the plane's origin value: z0 - (dzdx * (x0 - 0.5) + dzdy * (y0 - 0.5))", "[cpu][depth]") {
  // v0 = (4.5, 4.5, 0.1f), z falling by 2^-7 per pixel in x and rising by 2^-9 in y (the other two
  // vertices are 8 pixels away, their z exact in float). The bracket is exact:
  // -4/128 + 4/512 = -0.0234375, and 0.1f + 0.0234375 rounds once, to 0x1.f9999ap-4. Subtracting
  // the two terms one after the other would round twice and give 0x1.f99998p-4.
  const WindowPos v0{4.5f, 4.5f, 0.1f}, v1{12.5f, 4.5f, 0x1.333334p-5f}, v2{4.5f, 12.5f, 0x1.d9999ap-4f};
  const DepthPlane p = MakeDepthPlane(v0, v1, v2);
  CHECK(p.dzdx == -0x1p-7f);
  CHECK(p.dzdy == 0x1p-9f);
  CHECK(p.a0 == 0x1.f9999ap-4f);
  // Triangle setup swaps v1 and v2 here (negative area); the plane comes out the same.
  TriangleSetup t;
  REQUIRE(SetUpTriangle(v0, v1, v2, PixelRect{0, 0, 15, 15}, t));
  CHECK(t.swapped);
  CHECK(t.depth.a0 == p.a0);
  CHECK(t.depth.dzdx == p.dzdx);
  CHECK(t.depth.dzdy == p.dzdy);
}

TEST_CASE("the depth plane is evaluated with fused multiply-adds, then clamped", "[cpu][depth]") {
  // dzdx = 1/3 as float = 0x1.555556p-2, so 3 * dzdx = 1 + 2^-25 exactly; fused with a0 = -1 that
  // leaves 2^-25. Rounding the product first would give 1 - 1 = 0.
  const DepthPlane plane{-1.0f, 0x1.555556p-2f, 0.0f};
  CHECK(DepthAt(plane, 3, 7) == 0x1p-25f);
  volatile float product = plane.dzdx * 3.0f;
  CHECK(product + plane.a0 == 0.0f);
  // Clamped to [0, 1].
  CHECK(DepthAt(DepthPlane{-0.5f, 0.0f, 0.0f}, 0, 0) == 0.0f);
  CHECK(DepthAt(DepthPlane{1.5f, 0.0f, 0.0f}, 0, 0) == 1.0f);
  CHECK(DepthAt(DepthPlane{0.5f, 0.25f, -0.5f}, 2, 1) == 0.5f);
  // As SSE's min then max: NaN becomes 1, -0 becomes +0.
  CHECK(ClampDepth(std::nanf("")) == 1.0f);
  CHECK(ClampDepth(-0.0f) == 0.0f);
  CHECK_FALSE(std::signbit(ClampDepth(-0.0f)));
  CHECK(ClampDepth(-INFINITY) == 0.0f);
  CHECK(ClampDepth(INFINITY) == 1.0f);
}

TEST_CASE("a triangle with zero float area but non-zero snapped area has depth NaN, clamped to 1", "[cpu][depth]") {
  // Window vertices (0.5, 0.5), (1.5, 0.5 + d), (2.5, 0.5 + 2d) with d = 0x1.f8p-10: collinear in
  // float (e = -1 * 2d, f = -d * 2, e - f = 0, ooa = inf, gradients 0 * inf = NaN), but snapped
  // (0, 0), (256, 0), (512, 1) since 256d = 0.49 rounds to 0 and 512d = 0.98 to 1. The only pixel
  // covered is (0, 0): at v0, on the top edge v0 v1 and on the left edge v2 v0.
  const float d = 0x1.f8p-10f;
  TriangleSetup t;
  REQUIRE(SetUpTriangle({0.5f, 0.5f, 0.5f}, {1.5f, 0.5f + d, 0.5f}, {2.5f, 0.5f + 2 * d, 0.5f}, PixelRect{0, 0, 15, 15},
                        t));
  CHECK(std::isnan(PlaneDepth(t.depth, 0.0f, 0.0f)));
  CHECK(DepthAt(t.depth, 0, 0) == 1.0f);
  CHECK(Covers(t, 0, 0));
  CHECK_FALSE(Covers(t, 1, 0));
  CHECK_FALSE(Covers(t, 2, 0));
  // Standard depth: 1.0 never passes LESS against the clear. Reversed Z: it passes GREATER.
  Framebuffer standard = Cleared(4, 4, 0u), reversed = Cleared(4, 4, 0u, DepthCompare::kGreater);
  ShadeSpan(standard, 0, Span{0, 1}, t.depth, 7u);
  ShadeSpan(reversed, 0, Span{0, 1}, t.depth, 7u);
  CHECK(standard.colour_word(0) == 0u);
  CHECK(reversed.colour_word(0) == 7u);
  CHECK(reversed.depth[0] == 1.0f);
}

TEST_CASE("depth test LESS: equal depth is rejected, nearer passes and writes", "[cpu][depth]") {
  Framebuffer fb = Cleared(4, 4, 0x11223344u);
  const DepthPlane plane{0.5625f, 0.0f, 0.0f};
  CHECK(fb.depth[5] == 1.0f);
  CHECK(fb.colour_word(5) == 0x11223344u);
  CHECK(ShadeFragment(fb, 1, 1, plane, 0xaabbccddu));
  CHECK(fb.depth[5] == 0.5625f);
  CHECK(fb.colour_word(5) == 0xaabbccddu);
  // Same depth again, another colour: LESS fails, nothing changes.
  CHECK_FALSE(ShadeFragment(fb, 1, 1, plane, 0x01020304u));
  CHECK(fb.colour_word(5) == 0xaabbccddu);
  CHECK_FALSE(DepthTest(DepthCompare::kLess, 0.5625f, 0.5625f));
  // A hair nearer passes.
  const DepthPlane nearer{std::nextafter(0.5625f, 0.0f), 0.0f, 0.0f};
  CHECK(ShadeFragment(fb, 1, 1, nearer, 0x01020304u));
  CHECK(fb.colour_word(5) == 0x01020304u);
  // A fragment at exactly 1.0 never passes against the cleared buffer.
  CHECK_FALSE(ShadeFragment(fb, 2, 2, DepthPlane{1.0f, 0.0f, 0.0f}, 0x01020304u));
  CHECK(fb.colour_word(10) == 0x11223344u);
}

TEST_CASE("reversed Z: cleared to 0, GREATER rejects equal depth, farther fragments fail", "[cpu][depth]") {
  Framebuffer fb = Cleared(4, 4, 0x11223344u, DepthCompare::kGreater);
  CHECK(fb.depth[5] == 0.0f);
  CHECK(ShadeFragment(fb, 1, 1, DepthPlane{0.25f, 0.0f, 0.0f}, 0xaabbccddu));
  CHECK(fb.depth[5] == 0.25f);
  CHECK_FALSE(ShadeFragment(fb, 1, 1, DepthPlane{0.25f, 0.0f, 0.0f}, 0x01020304u));   // equal
  CHECK_FALSE(ShadeFragment(fb, 1, 1, DepthPlane{0.125f, 0.0f, 0.0f}, 0x01020304u));  // farther
  CHECK(fb.colour_word(5) == 0xaabbccddu);
  CHECK(ShadeFragment(fb, 1, 1, DepthPlane{0.5f, 0.0f, 0.0f}, 0x01020304u));  // nearer
  CHECK(fb.colour_word(5) == 0x01020304u);
  CHECK_FALSE(ShadeFragment(fb, 2, 2, DepthPlane{0.0f, 0.0f, 0.0f}, 0x01020304u));  // at the clear
  CHECK(DepthTest(DepthCompare::kGreater, 0.5f, 0.25f));
  CHECK_FALSE(DepthTest(DepthCompare::kGreater, 0.25f, 0.25f));
}

TEST_CASE("span shading equals fragment-by-fragment shading", "[cpu][depth]") {
  const DepthCompare op = GENERATE(DepthCompare::kLess, DepthCompare::kGreater);
  Framebuffer a = Cleared(32, 1, 0u, op), b = Cleared(32, 1, 0u, op);
  const DepthPlane first{0.8f, -0.01f, 0.0f}, second{0.2f, 0.03f, 0.0f};
  ShadeSpan(a, 0, Span{0, 32}, first, 1u);
  ShadeSpan(a, 0, Span{3, 29}, second, 2u);
  for (int px = 0; px < 32; ++px) ShadeFragment(b, px, 0, first, 1u);
  for (int px = 3; px < 29; ++px) ShadeFragment(b, px, 0, second, 2u);
  CHECK(a.colour.rgba == b.colour.rgba);
  for (std::size_t i = 0; i < 32; ++i) CHECK(a.depth[i] == b.depth[i]);
  if (op == DepthCompare::kLess) {
    CHECK(a.colour_word(3) == 2u);   // 0.29 < 0.77
    CHECK(a.colour_word(28) == 1u);  // 1.04 clamped to 1, not < 0.52
  } else {
    CHECK(a.colour_word(3) == 1u);   // 0.29 not > 0.77
    CHECK(a.colour_word(28) == 2u);  // 1 > 0.52
  }
}
