// The whole CPU renderer: watertightness, closed meshes, colours, draw order, thread-count
// independence, and agreement with a pixel-by-pixel evaluation of the same stages.
#include "cpu/chunk_assembly.hpp"
#include "cpu/coverage_counts.hpp"
#include "cpu/cpu_renderer.hpp"
#include "cpu/fragment_ops.hpp"
#include "support/catch.hpp"
#include "test_scenes.hpp"

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <thread>
#include <utility>

using namespace twinraster;
using namespace twinraster::cputest;

namespace {

// Random overlapping triangles in two draws: one with w = 1 (clip space directly), one with a
// perspective-like matrix (w = z, some vertices behind the camera), many of them clipped, and
// exact duplicates with other colours (depth ties).
DrawList RandomTriangles(std::uint32_t width, std::uint32_t height, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> xy(-1.6f, 1.6f), z(-0.3f, 1.3f), depth(-0.5f, 3.0f);
  DrawList list;
  list.width = width;
  list.height = height;
  list.background = {1, 2, 3};
  for (int m = 0; m < 2; ++m) {
    DrawMesh mesh;
    for (int t = 0; t < count; ++t) {
      const auto base = static_cast<std::uint32_t>(mesh.positions.size());
      for (int k = 0; k < 3; ++k) mesh.positions.push_back({xy(rng), xy(rng), m == 0 ? z(rng) : depth(rng)});
      mesh.triangles.push_back({base, base + 1, base + 2});
      mesh.colours.push_back(
          {static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng()), static_cast<std::uint8_t>(rng())});
      if (t % 7 == 0) {  // the same triangle again, another colour: LESS keeps the first
        mesh.triangles.push_back({base, base + 1, base + 2});
        mesh.colours.push_back({static_cast<std::uint8_t>(rng()), 0, 0});
      }
    }
    list.meshes.push_back(mesh);
  }
  glm::mat4 perspective(1.0f);
  perspective[2][2] = 1.02f;  // z' = 1.02 z - 0.1
  perspective[3][2] = -0.1f;
  perspective[2][3] = 1.0f;  // w' = z
  perspective[3][3] = 0.0f;
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  list.draws.push_back(DrawCall{1, perspective});
  return list;
}

// The same stages without spans, bands or threads: every pixel of every box tested on its own.
Image RenderPixelByPixel(const DrawList& list) {
  const cpu::TriangleChunks chunks = cpu::ProcessGeometry(list, 3);
  std::vector<cpu::TriangleSetup> triangles;
  for (const auto& chunk : chunks) triangles.insert(triangles.end(), chunk.begin(), chunk.end());
  cpu::Framebuffer fb(list.width, list.height,
                      list.reversed_z ? cpu::DepthCompare::kGreater : cpu::DepthCompare::kLess);
  cpu::ClearRows(fb, 0, static_cast<int>(list.height), cpu::PackRgba(list.background));
  for (const cpu::TriangleSetup& t : triangles) {
    for (int py = t.bounds.y0; py <= t.bounds.y1; ++py) {
      for (int px = t.bounds.x0; px <= t.bounds.x1; ++px) {
        if (cpu::Covers(t, px, py)) cpu::ShadeFragment(fb, px, py, t.depth, t.colour);
      }
    }
  }
  return std::move(fb.colour);
}

}  // namespace

TEST_CASE("a fan inside the image covers every pixel at most once, and the inside exactly once", "[cpu][render]") {
  const DrawList fan = Fan(97, 83, {0.03f, -0.05f}, 0.8f, 17);
  const cpu::CoverageCounts counts = cpu::CountCoverage(fan);
  const auto& ring = fan.meshes[0].positions;
  const auto window = [&](const glm::vec3& p) {
    return glm::dvec2((p.x + 1.0) * 0.5 * fan.width, (p.y + 1.0) * 0.5 * fan.height);
  };
  std::size_t covered = 0;
  for (std::uint32_t y = 0; y < fan.height; ++y) {
    for (std::uint32_t x = 0; x < fan.width; ++x) {
      INFO("pixel " << x << "," << y);
      REQUIRE(counts.total(x, y) <= 1);
      covered += counts.total(x, y);
      // Well inside the ring polygon (more than a hundredth of a pixel from its outline): covered.
      const glm::dvec2 c(x + 0.5, y + 0.5);
      bool inside = true;
      const std::size_t n = ring.size() - 1;
      for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = window(ring[1 + i]), b = window(ring[1 + (i + 1) % n]);
        const glm::dvec2 e = b - a;
        const double side = (e.x * (c.y - a.y) - e.y * (c.x - a.x)) / std::hypot(e.x, e.y);
        inside = inside && side > 0.01;
      }
      if (inside) REQUIRE(counts.total(x, y) == 1);
    }
  }
  CHECK(covered > 2000);
}

TEST_CASE("a clipped fan larger than the image covers every pixel exactly once", "[cpu][render]") {
  // Ring radius 3 in clip space: every triangle crosses the x or y planes, and the polygon
  // contains the whole view square, so clipping must leave no gap and no overlap.
  const DrawList fan = Fan(64, 48, {0.1f, 0.07f}, 3.0f, 16);
  const cpu::CoverageCounts counts = cpu::CountCoverage(fan);
  for (std::uint32_t y = 0; y < fan.height; ++y) {
    for (std::uint32_t x = 0; x < fan.width; ++x) {
      INFO("pixel " << x << "," << y);
      REQUIRE(counts.total(x, y) == 1);
    }
  }
}

TEST_CASE("closed cubes: every pixel is covered by as many front-facing as back-facing triangles", "[cpu][render]") {
  // Rotated cubes, one inside the image and one cut by the image's left edge.
  const DrawList list = CubeScene(
      151, 127, {{{0.4, -0.2, 6.0}, {0.3, 0.8, 0.5}, 37.0, 1.0}, {{-3.2, 0.6, 7.5}, {1.0, 0.2, 0.1}, 61.0, 1.3}});
  const cpu::CoverageCounts counts = cpu::CountCoverage(list);
  std::size_t covered = 0;
  for (std::uint32_t y = 0; y < list.height; ++y) {
    for (std::uint32_t x = 0; x < list.width; ++x) {
      const std::size_t i = counts.index(x, y);
      INFO("pixel " << x << "," << y);
      REQUIRE(counts.kept[i] == counts.swapped[i]);
      REQUIRE(counts.kept[i] <= 2);  // two cubes may overlap
      covered += counts.kept[i] != 0;
    }
  }
  CHECK(covered > 2000);
}

TEST_CASE("colours: the triangle's colour with alpha 255 over the background", "[cpu][render]") {
  DrawList list;
  list.width = 8;
  list.height = 8;
  list.background = {7, 8, 9};
  DrawMesh mesh;
  // Clip-space square (-0.5, -0.5) .. (0.5, 0.5): window [2, 6]^2, pixels 2..5 in both directions.
  mesh.positions = {{-0.5f, -0.5f, 0.5f}, {0.5f, -0.5f, 0.5f}, {0.5f, 0.5f, 0.5f}, {-0.5f, 0.5f, 0.5f}};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}};
  mesh.colours = {{200, 100, 50}, {200, 100, 50}};
  list.meshes.push_back(mesh);
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  const Image image = cpu::RenderOnCpu(list);
  REQUIRE(image.width == 8);
  REQUIRE(image.height == 8);
  for (std::uint32_t y = 0; y < 8; ++y) {
    for (std::uint32_t x = 0; x < 8; ++x) {
      const bool inside = x >= 2 && x <= 5 && y >= 2 && y <= 5;
      const std::uint8_t* p = image.pixel(x, y);
      INFO("pixel " << x << "," << y);
      CHECK(p[0] == (inside ? 200 : 7));
      CHECK(p[1] == (inside ? 100 : 8));
      CHECK(p[2] == (inside ? 50 : 9));
      CHECK(p[3] == 255);
    }
  }
}

TEST_CASE("depth ties keep the earlier draw (LESS), nearer later draws win", "[cpu][render]") {
  DrawList list;
  list.width = 16;
  list.height = 16;
  DrawMesh mesh;
  mesh.positions = {{-1.0f, -1.0f, 0.5f}, {3.0f, -1.0f, 0.5f}, {-1.0f, 3.0f, 0.5f}};
  mesh.triangles = {{0, 1, 2}};
  mesh.colours = {{255, 0, 0}};
  list.meshes.push_back(mesh);
  mesh.colours = {{0, 255, 0}};
  list.meshes.push_back(mesh);
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  list.draws.push_back(DrawCall{1, glm::mat4(1.0f)});  // same depth: rejected everywhere
  Image image = cpu::RenderOnCpu(list);
  CHECK(image.pixel(5, 5)[0] == 255);
  CHECK(image.pixel(5, 5)[1] == 0);

  glm::mat4 nearer(1.0f);
  nearer[3][2] = -0.25f;  // z' = z - 0.25
  list.draws.push_back(DrawCall{1, nearer});
  image = cpu::RenderOnCpu(list);
  CHECK(image.pixel(5, 5)[0] == 0);
  CHECK(image.pixel(5, 5)[1] == 255);
}

TEST_CASE("reversed Z: nearer still wins, ties keep the earlier draw", "[cpu][render]") {
  // Two cubes, the second in front of the first: standard and reversed Z give the same picture.
  Placed back{{0.3, 0.1, 9.0}, {0.2, 1.0, 0.3}, 25.0, 1.5}, front{{-0.4, -0.2, 6.5}, {1.0, 0.4, 0.0}, 40.0, 1.0};
  const DrawList standard = CubeScene(160, 120, {back, front});
  DrawList reversed = CubeScene(160, 120, {back, front}, /*reversed_z=*/true);
  REQUIRE(reversed.reversed_z);
  const Image a = cpu::RenderOnCpu(standard), b = cpu::RenderOnCpu(reversed);
  std::size_t differing = 0;
  for (std::size_t i = 0; i < a.rgba.size(); i += 4)
    differing += a.rgba[i] != b.rgba[i] || a.rgba[i + 1] != b.rgba[i + 1] || a.rgba[i + 2] != b.rgba[i + 2];
  // Depth rounds differently, so a pixel where two faces nearly meet may differ; the cubes do not
  // touch, so the pictures should agree everywhere.
  CHECK(differing == 0);

  // Ties: the same triangle twice, in another colour: the first stays with GREATER too.
  DrawList list;
  list.width = list.height = 16;
  list.reversed_z = true;
  DrawMesh mesh;
  mesh.positions = {{-1.0f, -1.0f, 0.5f}, {3.0f, -1.0f, 0.5f}, {-1.0f, 3.0f, 0.5f}};
  mesh.triangles = {{0, 1, 2}, {0, 1, 2}};
  mesh.colours = {{255, 0, 0}, {0, 255, 0}};
  list.meshes.push_back(mesh);
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  const Image tie = cpu::RenderOnCpu(list);
  CHECK(tie.pixel(5, 5)[0] == 255);
  CHECK(tie.pixel(5, 5)[1] == 0);
}

TEST_CASE("the image is the same for any thread count", "[cpu][render][threads]") {
  const DrawList list = RandomTriangles(173, 131, 300, 7u);
  const Image one = cpu::RenderOnCpu(list, cpu::CpuOptions{1});
  for (unsigned threads : {2u, 3u, 7u, 0u}) {
    INFO("threads " << threads);
    const Image other = cpu::RenderOnCpu(list, cpu::CpuOptions{threads});
    CHECK(other.rgba == one.rgba);
  }
  const DrawList cubes = CubeScene(600, 600, {{{-1.5, 0, 7}}, {{1.25, 2, 7.5}}});
  const Image cubes_one = cpu::RenderOnCpu(cubes, cpu::CpuOptions{1});
  CHECK(cpu::RenderOnCpu(cubes, cpu::CpuOptions{2}).rgba == cubes_one.rgba);
  CHECK(cpu::RenderOnCpu(cubes, cpu::CpuOptions{3}).rgba == cubes_one.rgba);
}

TEST_CASE(
    "threads 0: one thread within kOneThreadPixels and kOneThreadTriangles, every core beyond either, and never "
    "more than one per 16-row band",
    "[cpu][render][threads]") {
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  const auto used = [](const DrawList& list, unsigned threads = 0) {
    cpu::CpuTimings t;
    cpu::RenderOnCpu(list, cpu::CpuOptions{threads}, &t);
    return t.threads;
  };
  CHECK(cpu::kOneThreadPixels == 1024 * 1024);  // as render --help and docs/commands.md say
  CHECK(cpu::kOneThreadTriangles == 4096);
  CHECK(used(Fan(1024, 1024, {0, 0}, 0.5f, 12)) == 1);
  CHECK(used(Fan(1024, 1025, {0, 0}, 0.5f, 12)) == std::min(cores, 65u));  // 65 bands of 16 rows
  CHECK(used(Fan(64, 64, {0, 0}, 0.5f, 4096)) == 1);
  CHECK(used(Fan(64, 64, {0, 0}, 0.5f, 4097)) == std::min(cores, 4u));
  CHECK(used(Fan(64, 32, {0, 0}, 0.5f, 12), 5) == 2);  // asked for 5; 2 bands
  CHECK(used(Fan(64, 64, {0, 0}, 0.5f, 12), 3) == 3);
}

TEST_CASE("the image is the same for any chunking of the geometry, big draws sliced", "[cpu][render][chunks]") {
  // Two draws of ~340 triangles each, and the cube scene's many small draws.
  const DrawList list = RandomTriangles(173, 131, 300, 11u);
  const Image whole = RenderPixelByPixel(list);
  const DrawList cubes = CubeScene(200, 150, {{{-1.5, 0, 7}}, {{1.25, 2, 7.5}}, {{0, -1, 6}}, {{0.5, 0.5, 9}}});
  const Image cubes_whole = cpu::RenderOnCpu(cubes, cpu::CpuOptions{1, 1u << 20});
  for (const std::size_t chunk : {1u, 5u, 12u, 13u, 100u, 299u, 1000u}) {
    for (const unsigned threads : {1u, 2u, 3u}) {
      INFO("chunk " << chunk << ", threads " << threads);
      CHECK(cpu::RenderOnCpu(list, cpu::CpuOptions{threads, chunk}).rgba == whole.rgba);
      CHECK(cpu::RenderOnCpu(cubes, cpu::CpuOptions{threads, chunk}).rgba == cubes_whole.rgba);
    }
  }
}

TEST_CASE("PlanChunks: whole draws within the budgets, bigger draws sliced, vertices shaded once", "[cpu][chunks]") {
  DrawList list;
  DrawMesh small, big;
  small.positions.assign(4, glm::vec3(0.0f));
  small.triangles.assign(3, {0, 1, 2});
  big.positions.assign(30, glm::vec3(0.0f));
  big.triangles.assign(25, {0, 1, 2});
  list.meshes = {small, big};
  for (const std::uint32_t mesh : {0u, 0u, 0u, 1u, 0u}) list.draws.push_back(DrawCall{mesh, glm::mat4(1.0f)});
  // Budget 10 triangles and 10 vertices: two small draws (6 triangles, 8 vertices) fit, a third
  // would break the vertex budget; the big draw is sliced 10 + 10 + 5.
  const std::vector<cpu::GeometryChunk> chunks = cpu::PlanChunks(list, cpu::ChunkBudget{10, 10});
  REQUIRE(chunks.size() == 6);
  REQUIRE((chunks[0].draw_begin == 0 && chunks[0].draw_end == 2 && !chunks[0].slice));
  REQUIRE((chunks[1].draw_begin == 2 && chunks[1].draw_end == 3 && !chunks[1].slice));
  for (int i = 0; i < 3; ++i) {
    const cpu::GeometryChunk& c = chunks[static_cast<std::size_t>(2 + i)];
    INFO("slice " << i);
    REQUIRE((c.slice && c.draw_begin == 3 && c.draw_end == 4));
    REQUIRE(c.triangle_begin == static_cast<std::size_t>(10 * i));
    REQUIRE(c.triangle_end == std::min<std::size_t>(25, static_cast<std::size_t>(10 * i + 10)));
    REQUIRE(c.shade_vertices == (i == 0));
  }
  REQUIRE((chunks[5].draw_begin == 4 && chunks[5].draw_end == 5 && chunks[5].shade_vertices));
}

TEST_CASE("spans, bands and threads give what pixel-by-pixel evaluation gives", "[cpu][render]") {
  for (unsigned seed : {1u, 2u, 3u}) {
    const DrawList list = RandomTriangles(120, 90, 200, seed);
    cpu::CpuTimings timings;
    const Image fast = cpu::RenderOnCpu(list, cpu::CpuOptions{2}, &timings);
    CHECK(fast.rgba == RenderPixelByPixel(list).rgba);
    DrawList reversed = list;
    reversed.reversed_z = true;
    CHECK(cpu::RenderOnCpu(reversed, cpu::CpuOptions{3}).rgba == RenderPixelByPixel(reversed).rgba);
    CHECK(timings.setup_ms >= 0.0);
    CHECK(timings.draw_ms > 0.0);
  }
}

TEST_CASE("narrow triangles, scanned pixel by pixel, give what the span walker's rule gives", "[cpu][render]") {
  // Thousands of triangles a few pixels wide at sub-pixel positions, many exactly on pixel
  // centres' rows and columns, some degenerate.
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> centre(-1.1f, 1.1f), size(0.0f, 0.2f), depth(0.1f, 0.9f);
  DrawList list;
  list.width = 64;
  list.height = 48;
  DrawMesh mesh;
  for (int t = 0; t < 4000; ++t) {
    const float cx = centre(rng), cy = centre(rng), z = depth(rng);
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (int k = 0; k < 3; ++k) {
      float x = cx + size(rng), y = cy + size(rng);
      if (t % 5 == 0) x = std::round(x * 32.0f) / 32.0f;  // on a pixel boundary's column
      mesh.positions.push_back({x, y, z});
    }
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.colours.push_back({static_cast<std::uint8_t>(t), static_cast<std::uint8_t>(t >> 8), 7});
  }
  list.meshes = {mesh};
  list.draws = {DrawCall{0, glm::mat4(1.0f)}};
  CHECK(cpu::RenderOnCpu(list, cpu::CpuOptions{2}).rgba == RenderPixelByPixel(list).rgba);
}

TEST_CASE("malformed draw lists are refused", "[cpu][render]") {
  DrawList list = Fan(16, 16, {0.0f, 0.0f}, 0.5f, 5);
  DrawList bad = list;
  bad.width = 0;
  CHECK_THROWS_AS(cpu::RenderOnCpu(bad), std::invalid_argument);
  bad = list;
  bad.height = 16385;
  CHECK_THROWS_AS(cpu::RenderOnCpu(bad), std::invalid_argument);
  bad = list;
  bad.draws[0].mesh = 1;
  CHECK_THROWS_AS(cpu::RenderOnCpu(bad), std::invalid_argument);
  bad = list;
  bad.meshes[0].triangles[2][1] = 99;
  CHECK_THROWS_AS(cpu::RenderOnCpu(bad), std::invalid_argument);
  bad = list;
  bad.meshes[0].colours.pop_back();
  CHECK_THROWS_AS(cpu::RenderOnCpu(bad), std::invalid_argument);
  CHECK_NOTHROW(cpu::RenderOnCpu(list));
}
