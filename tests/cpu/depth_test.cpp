// Stage 6 and 7: the depth plane, its evaluation, and the LESS depth test.
#include "cpu/depth_plane.hpp"
#include "cpu/fragment_ops.hpp"
#include "cpu/triangle_setup.hpp"

#include <catch2/catch.hpp>

#include <cmath>

using namespace twinraster::cpu;

TEST_CASE("depth plane through three window-space vertices", "[cpu][depth]") {
  // z = 0.25 + (x - 0.5) / 16 + (y - 0.5) / 32. The snapped area is negative, so setup swaps
  // vertices 1 and 2 before building the plane: with v0 = (0.5, 0.5), v1 = (0.5, 8.5),
  // v2 = (8.5, 0.5): e = 0, f = -64, ooa = 1/64, dzdx = -(0.5)(-0.125) = 0.0625,
  // dzdy = -(-0.25)(0.125) = 0.03125, a0 = 0.25 - 0 = 0.25.
  TriangleSetup t;
  REQUIRE(SetUpTriangle({0.5f, 0.5f, 0.25f}, {8.5f, 0.5f, 0.75f}, {0.5f, 8.5f, 0.5f},
                        PixelRect{0, 0, 15, 15}, t));
  CHECK(t.swapped);
  CHECK(t.depth.a0 == 0.25f);
  CHECK(t.depth.dzdx == 0.0625f);
  CHECK(t.depth.dzdy == 0.03125f);
  CHECK(DepthAt(t.depth, 4, 2) == 0.5625f);  // 0.25 + 4/16 + 2/32
  CHECK(DepthAt(t.depth, 0, 0) == 0.25f);
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
}

namespace {

Framebuffer Cleared(std::uint32_t w, std::uint32_t h, std::uint32_t colour) {
  Framebuffer fb(w, h);
  ClearRows(fb, 0, static_cast<int>(h), colour);
  return fb;
}

}  // namespace

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
  CHECK_FALSE(DepthTestLess(0.5625f, 0.5625f));
  // A hair nearer passes.
  const DepthPlane nearer{std::nextafter(0.5625f, 0.0f), 0.0f, 0.0f};
  CHECK(ShadeFragment(fb, 1, 1, nearer, 0x01020304u));
  CHECK(fb.colour_word(5) == 0x01020304u);
  // A fragment at exactly 1.0 never passes against the cleared buffer.
  CHECK_FALSE(ShadeFragment(fb, 2, 2, DepthPlane{1.0f, 0.0f, 0.0f}, 0x01020304u));
  CHECK(fb.colour_word(10) == 0x11223344u);
}

TEST_CASE("span shading equals fragment-by-fragment shading", "[cpu][depth]") {
  Framebuffer a = Cleared(32, 1, 0u), b = Cleared(32, 1, 0u);
  const DepthPlane first{0.8f, -0.01f, 0.0f}, second{0.2f, 0.03f, 0.0f};
  ShadeSpan(a, 0, Span{0, 32}, first, 1u);
  ShadeSpan(a, 0, Span{3, 29}, second, 2u);
  for (int px = 0; px < 32; ++px) ShadeFragment(b, px, 0, first, 1u);
  for (int px = 3; px < 29; ++px) ShadeFragment(b, px, 0, second, 2u);
  CHECK(a.colour.rgba == b.colour.rgba);
  for (std::size_t i = 0; i < 32; ++i) CHECK(a.depth[i] == b.depth[i]);
  CHECK(a.colour_word(3) == 2u);
  CHECK(a.colour_word(28) == 1u);  // 0.2 + 28 * 0.03 > 0.8 - 28 * 0.01
}
