// Stage 3: the viewport transform, with fma for shader vertices and without for clipped ones.
#include "cpu/lavapipe/viewport.hpp"

#include "support/catch.hpp"

using namespace twinraster::cpu;

TEST_CASE("viewport state for (0, 0, W, H) and depth [0, 1]", "[cpu][viewport]") {
  const ViewportState vp = MakeViewport(100, 60);
  CHECK(vp.scale[0] == 50.0f);
  CHECK(vp.translate[0] == 50.0f);
  CHECK(vp.scale[1] == 30.0f);
  CHECK(vp.translate[1] == 30.0f);
  CHECK(vp.scale[2] == 1.0f);
  CHECK(vp.translate[2] == 0.0f);

  const PixelRect region = DrawRegion(vp, 100, 60);
  CHECK(region.x0 == 0);
  CHECK(region.x1 == 99);
  CHECK(region.y0 == 0);
  CHECK(region.y1 == 59);
}

TEST_CASE("shader vertices use fmaf, clipped vertices do not", "[cpu][viewport]") {
  const ViewportState vp = MakeViewport(100, 100);  // scale = translate = 50
  // x = -0.7f = -0x1.666666p-1. Exactly, x * 50 + 50 = 15.000000596...: the float nearest is
  // 15 + 2^-20 (the fma result). Rounding x * 50 first gives -35 exactly, and -35 + 50 = 15.
  const glm::vec4 clip(-0.7f, 0.5f, 0.25f, 1.0f);
  const WindowPos fused = ViewportTransformShader(vp, clip);
  const WindowPos plain = ViewportTransformClipped(vp, clip);
  CHECK(fused.x == 0x1.e00002p+3f);
  CHECK(plain.x == 15.0f);
  CHECK(fused.y == 75.0f);
  CHECK(plain.y == 75.0f);
  CHECK(fused.z == 0.25f);
  CHECK(plain.z == 0.25f);
}

TEST_CASE("the perspective divide is a true division by w", "[cpu][viewport]") {
  const ViewportState vp = MakeViewport(64, 32);
  const WindowPos w = ViewportTransformShader(vp, glm::vec4(1.0f, -2.0f, 1.0f, 4.0f));
  CHECK(w.x == 40.0f);  // 0.25 * 32 + 32
  CHECK(w.y == 8.0f);   // -0.5 * 16 + 16
  CHECK(w.z == 0.25f);
}
