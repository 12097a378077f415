// Stage 7's depth tiles: the bound on a triangle's nearest fragment really bounds every fragment
// DepthAt computes, and skipping hidden triangles changes no pixel while skipping many.
#include "cpu/depth_tiles.hpp"

#include "cpu/cpu_renderer.hpp"
#include "cpu/lavapipe/setup.hpp"
#include "support/catch.hpp"
#include "test_scenes.hpp"

#include <algorithm>
#include <random>

using namespace twinraster;
using namespace twinraster::cpu;

TEST_CASE("NearestDepth bounds every covered fragment's depth, slivers and huge planes included",
          "[cpu][depth-tiles]") {
  std::mt19937 rng(20261123u);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f), z(-0.25f, 1.25f);
  const PixelRect region{0, 0, 4095, 4095};
  int checked = 0, plain = 0, tight = 0;
  for (int n = 0; n < 20000; ++n) {
    // Boxes of a few pixels to a few hundred, anywhere in a 4096 canvas; a third of the triangles
    // are slivers (the third vertex a hair off the first edge), whose planes are steep and ill-
    // conditioned.
    const float size = n % 2 == 0 ? 6.0f : 300.0f;
    const float ox = unit(rng) * 3700.0f, oy = unit(rng) * 3700.0f;
    WindowPos v[3];
    for (WindowPos& p : v) p = {ox + unit(rng) * size, oy + unit(rng) * size, z(rng)};
    if (n % 3 == 0) {
      const float t = unit(rng);
      v[2].x = v[0].x + t * (v[1].x - v[0].x) + (unit(rng) - 0.5f) * 0.02f;
      v[2].y = v[0].y + t * (v[1].y - v[0].y) + (unit(rng) - 0.5f) * 0.02f;
    }
    TriangleSetup t;
    if (!SetUpTriangle(v[0], v[1], v[2], region, t)) continue;
    const double nearest_less = NearestDepth(t.depth, t.bounds, DepthCompare::kLess);
    const double nearest_greater = NearestDepth(t.depth, t.bounds, DepthCompare::kGreater);
    for (int py = t.bounds.y0; py <= t.bounds.y1; ++py) {
      for (int px = t.bounds.x0; px <= t.bounds.x1; ++px) {
        if (!Covers(t, px, py)) continue;
        const float depth = DepthAt(t.depth, px, py);
        REQUIRE(depth >= nearest_less);
        REQUIRE(depth <= nearest_greater);
        ++checked;
      }
    }
    // Not vacuous: for ordinary triangles the bound is the plane's lowest value on the box, give
    // or take the rounding slack (which grows with the plane's size at the canvas origin).
    if (n % 3 != 0) {
      ++plain;
      const PixelRect& b = t.bounds;
      const float corner = std::min({DepthAt(t.depth, b.x0, b.y0), DepthAt(t.depth, b.x1, b.y0),
                                     DepthAt(t.depth, b.x0, b.y1), DepthAt(t.depth, b.x1, b.y1)});
      if (corner - nearest_less < 1e-3) ++tight;
    }
  }
  CHECK(checked > 1'000'000);
  CHECK(tight > plain * 9 / 10);
}

TEST_CASE("NearestDepth of a NaN plane bounds its fragments, which are clamped to 1", "[cpu][depth-tiles]") {
  const float nan = std::nanf("");
  const PixelRect box{0, 0, 3, 3};
  CHECK(NearestDepth(DepthPlane{nan, 0, 0}, box, DepthCompare::kLess) == 0.0);
  CHECK(NearestDepth(DepthPlane{nan, 0, 0}, box, DepthCompare::kGreater) == 1.0);
  CHECK(DepthAt(DepthPlane{nan, 0, 0}, 1, 1) == 1.0f);
}

TEST_CASE("depth tiles skip hidden triangles and change no pixel", "[cpu][render][depth-tiles]") {
  const bool reversed = GENERATE(false, true);
  INFO("reversed Z " << reversed);
  // Forty cubes in a column receding from the camera, nearest first, each a little off the one
  // before: after the first few, each is hidden almost everywhere. A chunk per cube, so the tiles
  // are refreshed between cubes.
  DrawList column = cputest::CubeScene(256, 200, {{{0, 0, 5}}}, reversed);
  column.draws.clear();
  for (int i = 0; i < 40; ++i) {
    const cputest::Placed cube{{0.05 * (i % 5), 0.04 * (i % 3), 5.0 + 0.5 * i}, {1, 1, 0}, 10.0 * i};
    column.draws.push_back(cputest::CubeScene(256, 200, {cube}, reversed).draws[0]);
  }
  for (const unsigned threads : {1u, 2u, 3u}) {
    for (const std::size_t chunk : {12u, 7u, 1000u}) {
      INFO("threads " << threads << ", chunk " << chunk);
      cpu::CpuTimings with_timings, without_timings;
      const Image with = cpu::RenderOnCpu(column, cpu::CpuOptions{threads, chunk, true}, &with_timings);
      const Image without = cpu::RenderOnCpu(column, cpu::CpuOptions{threads, chunk, false}, &without_timings);
      CHECK(with.rgba == without.rgba);
      CHECK(without_timings.hidden == 0);
      if (chunk < 1000) CHECK(with_timings.hidden > 200);  // most of 39 cubes' 12 triangles
    }
  }
}
