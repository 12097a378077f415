// SwiftShader's viewport transform and snapping (cpu/swiftshader/viewport.hpp): 1/16 pixel from
// pixel (0, 0)'s centre, straight from clip space, half to even; its outcodes.
#include "cpu/swiftshader/viewport.hpp"

#include "support/catch.hpp"

#include <cstdint>
#include <limits>

using namespace twinraster::cpu;

TEST_CASE("SwiftShader viewport: 16 W and 16 H with the half-pixel shift folded in", "[cpu][swiftshader][viewport]") {
  const SnapViewport vp = MakeSnapViewport(100, 50);
  CHECK(vp.wxf == 800.0f);  // W = 50, times 16
  CHECK(vp.hxf == 400.0f);
  CHECK(vp.x0xf == 792.0f);  // 16 W - 8: window x = W lands half a pixel right of pixel W - 1's centre
  CHECK(vp.y0xf == 392.0f);
  CHECK(vp.width == 100);
  CHECK(vp.height == 50);
}

TEST_CASE("SwiftShader snapping: the view volume's corners and centre in sixteenths of a pixel",
          "[cpu][swiftshader][viewport]") {
  const SnapViewport vp = MakeSnapViewport(100, 100);
  // Window x = 0 is half a pixel left of pixel 0's centre: -8; window x = 100 is 99.5 pixels right.
  const SnappedVertex left_top = SnapShaderVertex({-1.0f, -1.0f, 0.25f, 1.0f}, vp);
  CHECK(left_top.x == -8);
  CHECK(left_top.y == -8);
  const SnappedVertex right_bottom = SnapShaderVertex({2.0f, 2.0f, 1.0f, 2.0f}, vp);  // x / w = 1
  CHECK(right_bottom.x == 99 * 16 + 8);
  CHECK(right_bottom.y == 99 * 16 + 8);
  CHECK(right_bottom.z == 0.5f);  // z / w
  CHECK(right_bottom.rhw == 0.5f);
  const SnappedVertex centre = SnapShaderVertex({0.0f, 0.0f, 0.0f, 1.0f}, vp);
  CHECK(centre.x == 49 * 16 + 8);
}

TEST_CASE("SwiftShader snapping rounds half to even", "[cpu][swiftshader][viewport]") {
  // A 2-pixel viewport: x0xf = 8, wxf = 16, so x / w = k / 32 lands on 8 + k / 2 sixteenths.
  const SnapViewport vp = MakeSnapViewport(2, 2);
  CHECK(SnapShaderVertex({1.0f / 32, 0.0f, 0.0f, 1.0f}, vp).x == 8);   // 8.5 -> 8
  CHECK(SnapShaderVertex({3.0f / 32, 0.0f, 0.0f, 1.0f}, vp).x == 10);  // 9.5 -> 10
  CHECK(SnapShaderVertex({-1.0f / 32, 0.0f, 0.0f, 1.0f}, vp).x == 8);  // 7.5 -> 8
  CHECK(SnapShaderVertex({-3.0f / 32, 0.0f, 0.0f, 1.0f}, vp).x == 6);  // 6.5 -> 6
  CHECK(SnapPolygonVertex({3.0f / 32, 1.0f / 32, 0.0f, 1.0f}, vp).x == 10);
  CHECK(SnapPolygonVertex({3.0f / 32, 1.0f / 32, 0.0f, 1.0f}, vp).y == 8);
}

TEST_CASE("SwiftShader snapping: w = 0 reads as 1 of its sign, far values clamp, the polygon's do not",
          "[cpu][swiftshader][viewport]") {
  const SnapViewport vp = MakeSnapViewport(2, 2);
  CHECK(SnapShaderVertex({0.0f, 0.0f, 0.0f, 0.0f}, vp).rhw == 1.0f);
  CHECK(SnapShaderVertex({0.0f, 0.0f, 0.0f, -0.0f}, vp).rhw == -1.0f);
  // Clamped at the largest float below 2^31 before the conversion; far left does not fit at all.
  CHECK(SnapShaderVertex({1e30f, 0.0f, 0.0f, 1.0f}, vp).x == 2147483520);
  CHECK(SnapShaderVertex({-1e30f, 0.0f, 0.0f, 1.0f}, vp).x == std::numeric_limits<std::int32_t>::min());
  // The set-up's snapping of a clipped polygon has no clamp: far right is the integer indefinite too.
  CHECK(SnapPolygonVertex({1e30f, 0.0f, 0.0f, 1.0f}, vp).x == std::numeric_limits<std::int32_t>::min());
  CHECK(SnapPolygonVertex({1.0f, 0.0f, 0.0f, 0.0f}, vp).x == 24);  // w = 0: rhw 1, 8 + 16
}

TEST_CASE("SwiftShader outcodes: one bit per plane, and finite", "[cpu][swiftshader][viewport]") {
  const SnapViewport vp = MakeSnapViewport(2, 2);
  const auto code = [&](float x, float y, float z, float w) { return SnapShaderVertex({x, y, z, w}, vp).outcode; };
  CHECK(code(0, 0, 0.5f, 1) == kClipFinite);
  CHECK(code(1, -1, 1, 1) == kClipFinite);  // on the planes is inside
  CHECK(code(0, 0, 0, 1) == kClipFinite);
  CHECK(code(2, 0, 0.5f, 1) == (kClipRight | kClipFinite));
  CHECK(code(-2, 0, 0.5f, 1) == (kClipLeft | kClipFinite));
  CHECK(code(0, 2, 0.5f, 1) == (kClipTop | kClipFinite));
  CHECK(code(0, -2, 0.5f, 1) == (kClipBottom | kClipFinite));
  CHECK(code(0, 0, 2, 1) == (kClipFar | kClipFinite));
  CHECK(code(0, 0, -0.5f, 1) == (kClipNear | kClipFinite));
  // NaN fails every comparison: it is outside the left plane and not finite.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  CHECK(code(nan, 0, 0.5f, 1) == kClipLeft);
  CHECK(code(std::numeric_limits<float>::infinity(), 0, 0.5f, 1) == kClipRight);
}
