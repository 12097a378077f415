// Wireframe (polygonMode LINE) against the installed lavapipe: single lines whose pixels follow
// from llvmpipe's line rules by hand (docs/wireframe.md), then thousands of random triangle edges
// with endpoints on pixel centres, on subpixel ties and anywhere, leaving the viewport, at random
// depths, where the twin must give lavapipe's image exactly.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "support/catch.hpp"
#include "twin_support.hpp"

#include <glm/vec3.hpp>

#include <random>
#include <set>
#include <utility>
#include <vector>

using namespace twinraster;

namespace {

constexpr std::uint32_t kSize = 256;  // a power of two: window = (ndc + 1) · 128 is exact

// Window coordinates to the positions that reach them exactly (identity F, w = 1).
glm::vec3 At(double x, double y, double z) {
  return {static_cast<float>((x - 128.0) / 128.0), static_cast<float>((y - 128.0) / 128.0), static_cast<float>(z)};
}

// A wireframe list with identity F: each triangle given by window positions.
DrawList Wireframe(const std::vector<std::array<glm::vec3, 3>>& triangles, std::uint32_t size = kSize) {
  DrawList list;
  list.width = list.height = size;
  list.background = {255, 255, 255};
  list.wireframe = true;
  DrawMesh mesh;
  std::uint8_t shade = 0;
  for (const auto& t : triangles) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec3& p : t) mesh.positions.push_back(p);
    mesh.triangles.push_back({base, base + 1, base + 2});
    shade = static_cast<std::uint8_t>(shade + 37);
    mesh.colours.push_back({shade, static_cast<std::uint8_t>(255 - shade), 90});
  }
  list.meshes.push_back(mesh);
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  return list;
}

std::set<std::pair<int, int>> Drawn(const Image& image) {
  std::set<std::pair<int, int>> pixels;
  for (std::uint32_t y = 0; y < image.height; ++y)
    for (std::uint32_t x = 0; x < image.width; ++x)
      if (image.pixel(x, y)[0] != 255 || image.pixel(x, y)[1] != 255) pixels.insert({int(x), int(y)});
  return pixels;
}

// The pixels of the line a → b, drawn as the degenerate triangle (a, b, b): its edges are
// b → a, a → b and a zero-length b → b, which covers nothing.
std::set<std::pair<int, int>> LinePixels(glm::dvec2 a, glm::dvec2 b, Image* cpu_out = nullptr) {
  const DrawList list = Wireframe({{At(a.x, a.y, 0.5), At(b.x, b.y, 0.5), At(b.x, b.y, 0.5)}});
  const test::TwinResult r = test::RenderTwins(list);
  INFO(r.Describe());
  REQUIRE(r.Equal());
  if (cpu_out) *cpu_out = r.cpu;
  return Drawn(r.gpu);
}

std::set<std::pair<int, int>> Row(int y, int x0, int x1) {
  std::set<std::pair<int, int>> s;
  for (int x = x0; x <= x1; ++x) s.insert({x, y});
  return s;
}

}  // namespace

TEST_CASE("Wireframe lines by hand: a parallelogram half a pixel either side, no end caps", "[twin][wireframe]") {
  // Horizontal on pixel centres, either direction: x from 3 to 8 (the larger end is out).
  CHECK(LinePixels({3.5, 7.5}, {9.5, 7.5}) == Row(7, 3, 8));
  CHECK(LinePixels({9.5, 7.5}, {3.5, 7.5}) == Row(7, 3, 8));
  // On a pixel boundary (y = 5): the row above it.
  CHECK(LinePixels({2.5, 5.0}, {8.5, 5.0}) == Row(4, 2, 7));
  // Endpoints snap with util_iround. In Mesa 22.3.6 that is half AWAY from zero, not half to even
  // as triangles do: x = 10.5 + 1/512 is 2560.5 subpixels from the first centre, rounded up to
  // 2561, so pixel 10 is out. From Mesa 25 it is half to even: 2560, pixel 10's centre, so the
  // line is that of the first check, one pixel to the right.
  const bool even = test::SharedTwinRules().rules.lines_round_half_even;
  CHECK(LinePixels({10.5 + 1.0 / 512, 5.5}, {20.5 + 1.0 / 512, 5.5}) == (even ? Row(5, 10, 19) : Row(5, 11, 20)));
  // A diagonal through pixel centres: exactly (k, k) for k = 0..9.
  std::set<std::pair<int, int>> diagonal;
  for (int k = 0; k < 10; ++k) diagonal.insert({k, k});
  CHECK(LinePixels({0.5, 0.5}, {10.5, 10.5}) == diagonal);
  // Along the framebuffer's left edge (x = 0): column -1, so nothing.
  CHECK(LinePixels({0.0, 10.5}, {0.0, 40.5}).empty());
}

TEST_CASE("Wireframe: thousands of random edges, on centres, on subpixel ties, anywhere, GPU == twin",
          "[twin][wireframe]") {
  std::mt19937 rng(20261123u);
  std::uniform_int_distribution<int> pixel(-40, 295), kind(0, 5), sub(0, 255);
  std::uniform_real_distribution<double> anywhere(-60.0, 316.0), depth(-0.3, 1.3);
  const auto coordinate = [&] {
    const int k = pixel(rng);
    switch (kind(rng)) {
      case 0: return k + 0.5;                           // a pixel centre
      case 1: return k + 0.0;                           // a pixel corner
      case 2: return k + 0.5 + (sub(rng) + 0.5) / 256;  // a half-subpixel tie for snapping
      case 3: return k + sub(rng) / 256.0;              // on the subpixel grid
      default: return anywhere(rng);
    }
  };
  std::uint64_t drawn_pixels = 0;
  for (int scene = 0; scene < 8; ++scene) {
    std::vector<std::array<glm::vec3, 3>> triangles;
    for (int t = 0; t < 500; ++t) {
      std::array<glm::vec3, 3> tri;
      for (glm::vec3& p : tri) p = At(coordinate(), coordinate(), depth(rng));
      if (t % 5 == 0) tri[2] = tri[1];  // a single line (and a zero-length one)
      if (t % 7 == 0) {                 // a short one: a few subpixels to a pixel or two
        tri[1] = tri[0] + glm::vec3(static_cast<float>(sub(rng) - 128) / 4096.0f,
                                    static_cast<float>(sub(rng) - 128) / 8192.0f, 0.0f);
      }
      triangles.push_back(tri);
    }
    const DrawList list = Wireframe(triangles);
    const test::TwinResult r = test::RenderTwins(list);
    INFO("scene " << scene << ": " << r.Describe());
    REQUIRE(r.Equal());
    drawn_pixels += Drawn(r.cpu).size();
    // Chunked, with the depth tiles refreshed between chunks: still the same image.
    CHECK(cpu::RenderOnCpu(list, test::TwinOptions(cpu::CpuOptions{.threads = 2, .chunk_triangles = 7})).rgba ==
          r.cpu.rgba);
  }
  CHECK(drawn_pixels > 100000);  // the edges really draw: most of 8 x 65536 pixels
  test::RequireNoValidationMessages();
}
