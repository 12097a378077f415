// Pixels of small hand-made draw lists, checked against what the geometry says by hand.
#include "gpu/gpu_renderer.hpp"
#include "gpu_test_support.hpp"
#include "support/catch.hpp"

using namespace twinraster;
using namespace twinraster::gpu_test;

namespace {

const Rgb8 kBackground{10, 20, 30};

DrawList ListOf(std::uint32_t width, std::uint32_t height, std::vector<DrawMesh> meshes, std::vector<DrawCall> draws) {
  DrawList list;
  list.width = width;
  list.height = height;
  list.background = kBackground;
  list.meshes = std::move(meshes);
  list.draws = std::move(draws);
  return list;
}

// A square of two triangles (one of each winding) spanning window pixels [x0, x1) x [y0, y1).
std::vector<WindowTriangle> Square(double x0, double y0, double x1, double y1, Rgb8 colour) {
  return {{{x0, y0}, {x1, y0}, {x1, y1}, colour}, {{x0, y0}, {x0, y1}, {x1, y1}, colour}};
}

}  // namespace

TEST_CASE("A triangle with F = identity covers exactly the pixels inside it", "[gpu][pixels]") {
  // Window corners (1,1), (7,1), (1,6) in an 8x8 image. No pixel centre (x+0.5, y+0.5) lies on
  // an edge: covered exactly when x >= 1, y >= 1 and 5x + 6y < 35.5 (the long edge).
  const Rgb8 colour{200, 100, 50};
  const WindowTriangle triangle{{1, 1}, {7, 1}, {1, 6}, colour};
  gpu::GpuRenderer gpu;
  const Image image = gpu.Render(ListOf(8, 8, {MeshOf({triangle}, 8, 8)}, {DrawCall{0, glm::mat4(1.0f)}}));
  REQUIRE(image.width == 8);
  REQUIRE(image.height == 8);
  REQUIRE(image.rgba.size() == 8 * 8 * 4);

  int inside = 0;
  for (std::uint32_t y = 0; y < 8; ++y) {
    for (std::uint32_t x = 0; x < 8; ++x) {
      const bool covered = x >= 1 && y >= 1 && 10 * x + 12 * y < 71;
      INFO("pixel (" << x << ", " << y << ")");
      CHECK(RgbAt(image, x, y) == (covered ? colour : kBackground));
      CHECK(int{image.pixel(x, y)[3]} == 255);
      inside += covered;
    }
  }
  CHECK(inside == 15);  // rows 1..5 hold 5, 4, 3, 2, 1 pixels: the triangle is upright, top row first

  // The generic checker used below agrees and finds no pixel uncertain here.
  const PixelCheck check = CheckPixels(image, kBackground, {triangle});
  CHECK(check.mismatches == 0);
  CHECK(check.uncertain == 0);
  CHECK(check.triangle_pixels == 15);
}

TEST_CASE("The pixel checker fails on wrong images (the tests can fail)", "[gpu][pixels]") {
  const Rgb8 colour{200, 100, 50};
  const WindowTriangle triangle{{1, 1}, {7, 1}, {1, 6}, colour};
  gpu::GpuRenderer gpu;
  Image image = gpu.Render(ListOf(8, 8, {MeshOf({triangle}, 8, 8)}, {DrawCall{0, glm::mat4(1.0f)}}));
  REQUIRE(CheckPixels(image, kBackground, {triangle}).mismatches == 0);

  // A wrong colour, a wrong background, a shifted or flipped triangle: all are caught.
  CHECK(CheckPixels(image, kBackground, {{triangle.a, triangle.b, triangle.c, {200, 100, 51}}}).mismatches == 15);
  CHECK(CheckPixels(image, Rgb8{10, 20, 31}, {triangle}).mismatches == 64 - 15);
  CHECK(CheckPixels(image, kBackground, {{{2, 1}, {8, 1}, {2, 6}, colour}}).mismatches > 0);
  CHECK(CheckPixels(image, kBackground, {{{1, 7}, {7, 7}, {1, 2}, colour}}).mismatches > 0);
  // One changed byte, or a transparent pixel, is one mismatch.
  image.pixel(3, 2)[1] ^= 1;
  CHECK(CheckPixels(image, kBackground, {triangle}).mismatches == 1);
  image.pixel(3, 2)[1] ^= 1;
  image.pixel(0, 0)[3] = 254;
  CHECK(CheckPixels(image, kBackground, {triangle}).mismatches == 1);
}

TEST_CASE("The background is the clear colour exactly, for every 8-bit value", "[gpu][pixels]") {
  gpu::GpuRenderer gpu;
  for (int k = 0; k < 256; ++k) {
    DrawList list;
    list.width = 3;
    list.height = 2;
    list.background = Rgb8{static_cast<std::uint8_t>(k), static_cast<std::uint8_t>(255 - k),
                           static_cast<std::uint8_t>((k * 37) % 256)};
    const Image image = gpu.Render(list);
    INFO("background " << list.background);
    REQUIRE(CountColour(image, list.background) == 6);
    for (std::size_t i = 3; i < image.rgba.size(); i += 4) REQUIRE(int{image.rgba[i]} == 255);
  }
}

TEST_CASE("Triangle colours arrive exactly, for every 8-bit value", "[gpu][pixels]") {
  // 16x16 pixels, each its own square of two triangles with colour i = y * 16 + x: 512
  // triangles, so this also checks the corner-to-triangle numbering far past the first few.
  std::vector<WindowTriangle> squares;
  for (int i = 0; i < 256; ++i) {
    const double x = i % 16, y = i / 16;
    const Rgb8 colour{static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(255 - i),
                      static_cast<std::uint8_t>((i * 37) % 256)};
    for (const WindowTriangle& t : Square(x, y, x + 1, y + 1, colour)) squares.push_back(t);
  }
  gpu::GpuRenderer gpu;
  const Image image = gpu.Render(ListOf(16, 16, {MeshOf(squares, 16, 16)}, {DrawCall{0, glm::mat4(1.0f)}}));
  for (int i = 0; i < 256; ++i) {
    const auto x = static_cast<std::uint32_t>(i % 16), y = static_cast<std::uint32_t>(i / 16);
    INFO("pixel (" << x << ", " << y << ")");
    CHECK(RgbAt(image, x, y) == squares[2 * static_cast<std::size_t>(i)].colour);
  }
}

TEST_CASE("A nearer triangle hides a farther one whatever the draw order", "[gpu][pixels][depth]") {
  // Three squares over the same pixels [2, 6)^2 of an 8x8 image, at different depths.
  const Rgb8 near_colour{255, 0, 0}, far_colour{0, 255, 0}, other_far{0, 0, 255};
  const auto square = [](Rgb8 colour, float z) { return MeshOf(Square(2, 2, 6, 6, colour), 8, 8, z); };
  const std::vector<DrawMesh> meshes = {square(near_colour, 0.25f), square(far_colour, 0.75f), square(other_far, 0.75f),
                                        square(near_colour, 1.0f)};
  const glm::mat4 identity(1.0f);
  gpu::GpuRenderer gpu;
  const auto expect_square = [&](std::vector<DrawCall> draws, std::optional<Rgb8> visible) {
    const Image image = gpu.Render(ListOf(8, 8, meshes, std::move(draws)));
    const std::vector<WindowTriangle> expected = visible ? Square(2, 2, 6, 6, *visible) : std::vector<WindowTriangle>{};
    const PixelCheck check = CheckPixels(image, kBackground, expected);
    INFO(check.first_mismatch);
    CHECK(check.mismatches == 0);
    CHECK(check.triangle_pixels + check.uncertain == (visible ? 16u : 0u));
    CHECK(CountColour(image, kBackground) == (visible ? 64u - 16u : 64u));
  };
  SECTION("near after far") { expect_square({{1, identity}, {0, identity}}, near_colour); }
  SECTION("near before far") { expect_square({{0, identity}, {1, identity}}, near_colour); }
  // LESS: an equally deep fragment does not replace the one already there.
  SECTION("equal depth: the earlier draw stays") {
    expect_square({{1, identity}, {2, identity}}, far_colour);
    expect_square({{2, identity}, {1, identity}}, other_far);
  }
  // Depth is cleared to 1.0 and 1.0 is not LESS than 1.0.
  SECTION("depth 1.0 is hidden by the clear") { expect_square({{3, identity}}, std::nullopt); }
  // The depth comes from F too: the far square moved nearer (z 0.75 - 0.6 = 0.15) now wins.
  SECTION("depth through F") { expect_square({{0, identity}, {1, Translation(0, 0, -0.6f)}}, far_colour); }
}

TEST_CASE("Each triangle gets its own colour, in every mesh and instance", "[gpu][pixels]") {
  // Mesh 0 has three triangles, so mesh 1's colours start at 3 in the colour buffer. Mesh 1's
  // indices are local (0..5): vertexOffset must place them. Its two triangles have opposite
  // windings (no culling) and different colours.
  const Rgb8 a{1, 2, 3}, b{4, 5, 6}, c{7, 8, 9}, left{250, 128, 0}, right{0, 128, 250};
  const std::vector<WindowTriangle> first = {
      {{0, 14}, {2, 14}, {0, 16}, a}, {{3, 14}, {5, 14}, {3, 16}, b}, {{6, 14}, {8, 14}, {6, 16}, c}};
  const std::vector<WindowTriangle> second = {{{1, 1}, {7.3, 1}, {1, 6.6}, left},
                                              {{15, 1}, {9, 6.6}, {15, 6.6}, right}};
  gpu::GpuRenderer gpu;
  DrawList list = ListOf(16, 16, {MeshOf(first, 16, 16), MeshOf(second, 16, 16)}, {});

  SECTION("one instance of each mesh") {
    list.draws = {{1, glm::mat4(1.0f)}, {0, glm::mat4(1.0f)}};
    std::vector<WindowTriangle> all = second;
    all.insert(all.end(), first.begin(), first.end());
    const PixelCheck check = CheckPixels(gpu.Render(list), kBackground, all);
    INFO(check.first_mismatch);
    CHECK(check.mismatches == 0);
    CHECK(check.triangle_pixels > 30);
  }
  SECTION("two instances of the second mesh keep its colours") {
    // The second instance moves down 7 pixels: 7 * 2 / 16 in clip space.
    list.draws = {{1, glm::mat4(1.0f)}, {1, Translation(0, 0.875f, 0)}};
    std::vector<WindowTriangle> all = second;
    for (WindowTriangle t : second) {
      t.a.y += 7;
      t.b.y += 7;
      t.c.y += 7;
      all.push_back(t);
    }
    const Image image = gpu.Render(list);
    const PixelCheck check = CheckPixels(image, kBackground, all);
    INFO(check.first_mismatch);
    CHECK(check.mismatches == 0);
    CHECK(CountColour(image, left) > 2 * 10);
    CHECK(CountColour(image, right) > 2 * 10);
    CHECK(CountColour(image, a) == 0);
  }
}

TEST_CASE("An odd-sized image keeps its rows apart and top first", "[gpu][pixels]") {
  // 37 x 23: a row is 148 bytes, not a multiple of any copy alignment. A lopsided triangle
  // near the top left shows any transposition, flip or row-pitch error.
  const std::vector<WindowTriangle> triangles = {{{2.2, 1.3}, {30.7, 4.1}, {5.1, 20.6}, {9, 99, 199}},
                                                 {{33, 2}, {36.5, 22.5}, {31.2, 22}, {77, 0, 255}}};
  gpu::GpuRenderer gpu;
  const Image image = gpu.Render(ListOf(37, 23, {MeshOf(triangles, 37, 23)}, {DrawCall{0, glm::mat4(1.0f)}}));
  REQUIRE(image.width == 37);
  REQUIRE(image.height == 23);
  const PixelCheck check = CheckPixels(image, kBackground, triangles);
  INFO(check.first_mismatch);
  CHECK(check.mismatches == 0);
  CHECK(check.triangle_pixels > 200);
  CHECK(check.background_pixels > 300);
}

TEST_CASE("A triangle through the near plane is clipped and keeps its colour", "[gpu][pixels][clip]") {
  // Triangle 0 lies wholly right of the view (x > w) and is dropped; triangle 1 has its first
  // corner at z = -0.5, so the corner cut off by z = 0 is not drawn and the rest, drawn as a fan
  // of clipped triangles, must still read colour 1 (the flat triangle number survives clipping).
  const Rgb8 dropped{255, 255, 255}, kept{12, 34, 56};
  DrawMesh mesh;
  mesh.positions = {glm::vec3(1.5f, 0, 0.5f),         glm::vec3(2, 0, 0.5f),          glm::vec3(2, 0.5f, 0.5f),
                    glm::vec3(-0.75f, -0.75f, -0.5f), glm::vec3(0.75f, -0.75f, 0.5f), glm::vec3(-0.75f, 0.75f, 0.5f)};
  mesh.triangles = {{0, 1, 2}, {3, 4, 5}};
  mesh.colours = {dropped, kept};
  gpu::GpuRenderer gpu;
  const Image image = gpu.Render(ListOf(16, 16, {mesh}, {DrawCall{0, glm::mat4(1.0f)}}));
  // In window pixels the triangle is (2,2), (14,2), (2,14); z = 0 runs from (8,2) to (2,8).
  const std::vector<WindowTriangle> visible = {{{8, 2}, {14, 2}, {2, 14}, kept}, {{8, 2}, {2, 14}, {2, 8}, kept}};
  const PixelCheck check = CheckPixels(image, kBackground, visible);
  INFO(check.first_mismatch);
  CHECK(check.mismatches == 0);
  CHECK(CountColour(image, dropped) == 0);
  CHECK(CountColour(image, kept) > 40);
  CHECK(RgbAt(image, 3, 3) == kBackground);  // inside the cut-off corner
}

TEST_CASE("The vertex shader sums F's columns in the documented order", "[gpu][pixels][vertex]") {
  // gl_Position = ((F[0] * p.x + F[1] * p.y) + F[2] * p.z) + F[3]. With F[0].x = 1e8,
  // F[1].x = -1e8 and p.x = p.y, the first sum cancels exactly and clip x = p.z. Any order that
  // adds p.z to a 1e8-sized term first loses it (floats near 1e8 are 8 apart), so the triangle
  // below lands where the first test's triangle is only if the shader keeps this order.
  glm::mat4 F(0.0f);
  F[0] = glm::vec4(1e8f, 1, 0, 0);  // y = p.x
  F[1] = glm::vec4(-1e8f, 0, 0, 0);
  F[2] = glm::vec4(1, 0, 0, 0);     // x = p.z, after the cancellation
  F[3] = glm::vec4(0, 0, 0.5f, 1);  // depth 0.5, w = 1
  // Clip (x, y) = (-0.75, -0.75), (0.75, -0.75), (-0.75, 0.5): window (1,1), (7,1), (1,6).
  DrawMesh mesh;
  mesh.positions = {glm::vec3(-0.75f, -0.75f, -0.75f), glm::vec3(-0.75f, -0.75f, 0.75f), glm::vec3(0.5f, 0.5f, -0.75f)};
  mesh.triangles = {{0, 1, 2}};
  const Rgb8 colour{200, 100, 50};
  mesh.colours = {colour};

  // The test can fail: summed from the right, the same numbers give a different x.
  for (const glm::vec3& p : mesh.positions) {
    const float right_to_left = F[0].x * p.x + (F[1].x * p.y + (F[2].x * p.z + F[3].x));
    const float documented = ((F[0].x * p.x + F[1].x * p.y) + F[2].x * p.z) + F[3].x;
    CHECK(documented == p.z);
    CHECK(std::abs(right_to_left - p.z) >= 0.25f);
  }

  gpu::GpuRenderer gpu;
  const Image image = gpu.Render(ListOf(8, 8, {mesh}, {DrawCall{0, F}}));
  const PixelCheck check = CheckPixels(image, kBackground, {{{1, 1}, {7, 1}, {1, 6}, colour}});
  INFO(check.first_mismatch);
  CHECK(check.mismatches == 0);
  CHECK(check.triangle_pixels == 15);
}
