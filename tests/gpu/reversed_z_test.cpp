// Reversed Z (DrawList::reversed_z): depth is cleared to 0 and tested GREATER, so the larger
// depth is nearer. Checked with hand-made squares, the chapter's cubes, a renderer that switches
// between the two conventions, and the validation layer.
#include "gpu/gpu_renderer.hpp"
#include "gpu_test_support.hpp"
#include "support/catch.hpp"

using namespace twinraster;
using namespace twinraster::gpu_test;

namespace {

const Rgb8 kBackground{10, 20, 30};
const Rgb8 kRed{255, 0, 0}, kGreen{0, 255, 0}, kBlue{0, 0, 255}, kYellow{255, 255, 0}, kPurple{255, 0, 255},
    kCyan{0, 255, 255};

// A square of two triangles (one of each winding) over window pixels [2, 6)^2 of an 8x8 image.
std::vector<WindowTriangle> Square(Rgb8 colour) {
  return {{{2, 2}, {6, 2}, {6, 6}, colour}, {{2, 2}, {2, 6}, {6, 6}, colour}};
}

DrawMesh SquareAt(Rgb8 colour, float z) { return MeshOf(Square(colour), 8, 8, z); }

// Squares over the same pixels at different depths. Indices name them in the draw lists below.
enum SquareMesh : std::uint32_t { kAt075, kAt025, kAlsoAt025, kAt0, kAt1 };
const std::vector<DrawMesh> kSquares = {SquareAt(kRed, 0.75f), SquareAt(kGreen, 0.25f), SquareAt(kBlue, 0.25f),
                                        SquareAt(kPurple, 0.0f), SquareAt(kYellow, 1.0f)};

DrawList SquaresList(std::vector<std::uint32_t> order, bool reversed_z) {
  DrawList list;
  list.width = 8;
  list.height = 8;
  list.background = kBackground;
  list.meshes = kSquares;
  for (std::uint32_t mesh : order) list.draws.push_back(DrawCall{mesh, glm::mat4(1.0f)});
  list.reversed_z = reversed_z;
  return list;
}

// The image shows the square in colour `visible` (or no square) over the background.
void CheckSquare(const Image& image, std::optional<Rgb8> visible) {
  const PixelCheck check = CheckPixels(image, kBackground, visible ? Square(*visible) : std::vector<WindowTriangle>{});
  INFO(check.first_mismatch);
  CHECK(check.mismatches == 0);
  CHECK(check.triangle_pixels + check.uncertain == (visible ? 16u : 0u));
  CHECK(CountColour(image, kBackground) == (visible ? 64u - 16u : 64u));
}

std::size_t DifferentPixels(const Image& a, const Image& b) {
  std::size_t count = 0;
  for (std::uint32_t y = 0; y < a.height; ++y)
    for (std::uint32_t x = 0; x < a.width; ++x) count += RgbAt(a, x, y) != RgbAt(b, x, y);
  return count;
}

void RequireSilence(const gpu::GpuRenderer& gpu, const char* after) {
  INFO("after " << after);
  for (const std::string& message : gpu.ValidationMessages()) UNSCOPED_INFO(message);
  REQUIRE(gpu.ValidationMessages().empty());
}

}  // namespace

TEST_CASE("With reversed Z the larger depth is nearer, whatever the draw order", "[gpu][pixels][depth][reversed_z]") {
  gpu::GpuRenderer gpu;
  const auto render = [&](std::vector<std::uint32_t> order) { return gpu.Render(SquaresList(std::move(order), true)); };
  SECTION("near after far") { CheckSquare(render({kAt025, kAt075}), kRed); }
  SECTION("near before far") { CheckSquare(render({kAt075, kAt025}), kRed); }
  // GREATER is strict: an equally deep fragment does not replace the one already there.
  SECTION("equal depth: the earlier draw stays") {
    CheckSquare(render({kAt025, kAlsoAt025}), kGreen);
    CheckSquare(render({kAlsoAt025, kAt025}), kBlue);
  }
  // Depth is cleared to 0.0 and 0.0 is not GREATER than 0.0. The square is not clipped away
  // (0 <= z <= w): with standard depth the same square shows.
  SECTION("depth 0.0 is hidden by the clear") {
    CheckSquare(render({kAt0}), std::nullopt);
    CheckSquare(gpu.Render(SquaresList({kAt0}, false)), kPurple);
  }
  // The mirror image: 1.0, hidden by the standard clear, is the nearest depth here.
  SECTION("depth 1.0 shows, and hides everything behind it") {
    CheckSquare(render({kAt1}), kYellow);
    CheckSquare(render({kAt1, kAt075, kAt0}), kYellow);
    CheckSquare(gpu.Render(SquaresList({kAt1}, false)), std::nullopt);
  }
  // The depth comes from F too: the far square moved nearer (z 0.25 + 0.6 = 0.85) now wins.
  SECTION("depth through F") {
    DrawList list = SquaresList({kAt075, kAt025}, true);
    list.draws[1].F = Translation(0, 0, 0.6f);
    CheckSquare(gpu.Render(list), kGreen);
  }
  SECTION("no draws: only the background") { CheckSquare(render({}), std::nullopt); }
}

TEST_CASE("One renderer alternates standard and reversed Z renders", "[gpu][depth][reversed_z]") {
  // The same draws, far square (0.25) first: the flag alone decides which square is in front.
  // Each render reuses the same 8x8 images and switches pipeline and depth clear value.
  gpu::GpuRenderer gpu;
  for (const bool reversed_z : {false, true, true, false, true, false, false, true}) {
    INFO("reversed_z " << reversed_z);
    CheckSquare(gpu.Render(SquaresList({kAt025, kAt075}, reversed_z)), reversed_z ? kRed : kGreen);
  }
  // Another size in between, then back to 8x8 (new images each time).
  CHECK(CountColour(gpu.Render(ChapterInstances(64, 48, true)), kBlue) > 100);
  CheckSquare(gpu.Render(SquaresList({kAt075, kAt025}, true)), kRed);
  CheckSquare(gpu.Render(SquaresList({kAt075, kAt025}, false)), kGreen);
}

TEST_CASE("The chapter's cubes look the same with reversed Z", "[gpu][depth][reversed_z]") {
  gpu::GpuRenderer gpu;
  const Image standard = gpu.Render(ChapterInstances(600, 600, false));
  const Image reversed = gpu.Render(ChapterInstances(600, 600, true));
  // The near faces (blue), the left cube's right face (green), the right cube's bottom (cyan)
  // and left (yellow) faces show; the far faces (red) and the tops (purple) stay hidden.
  CHECK(CountColour(reversed, kBlue) > 10000);
  CHECK(CountColour(reversed, kGreen) > 1000);
  CHECK(CountColour(reversed, kCyan) > 1000);
  CHECK(CountColour(reversed, kYellow) > 500);
  CHECK(CountColour(reversed, kRed) == 0);
  CHECK(CountColour(reversed, kPurple) == 0);
  CHECK(CountColour(reversed, {255, 255, 255}) > 600 * 600 / 2);  // the canvas's white
  // Depth rounds differently in the two conventions, but no two faces here come close enough in
  // depth for that to change a pixel.
  CHECK(DifferentPixels(standard, reversed) == 0);

  // The tests can fail: a reversed-Z test on a standard projection keeps the farthest faces.
  DrawList mismatched = ChapterInstances(600, 600, false);
  mismatched.reversed_z = true;
  const Image wrong = gpu.Render(mismatched);
  CHECK(CountColour(wrong, kRed) > 10000);
  CHECK(CountColour(wrong, kBlue) == 0);
}

TEST_CASE("Validation stays silent with reversed Z and when switching conventions", "[gpu][validation][reversed_z]") {
  gpu::GpuRenderer gpu(gpu::GpuOptions{.device = "", .validation = true});
  RequireSilence(gpu, "construction");

  CheckSquare(gpu.Render(SquaresList({kAt025, kAt075, kAt0}, true)), kRed);
  RequireSilence(gpu, "reversed squares, 8x8");

  // Same size: the depth image is reused with the other clear value and pipeline.
  CheckSquare(gpu.Render(SquaresList({kAt025, kAt075}, false)), kGreen);
  RequireSilence(gpu, "standard squares, 8x8");
  CheckSquare(gpu.Render(SquaresList({kAt025, kAt075}, true)), kRed);
  RequireSilence(gpu, "reversed squares again, 8x8");

  CHECK(CountColour(gpu.Render(ChapterInstances(600, 600, true)), kBlue) > 10000);
  RequireSilence(gpu, "reversed cubes, 600x600");
  CHECK(CountColour(gpu.Render(ChapterInstances(600, 600, false)), kBlue) > 10000);
  RequireSilence(gpu, "standard cubes, 600x600");
}
