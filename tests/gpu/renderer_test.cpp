// The renderer's contract beyond pixels: device choice, sizes, malformed input, empty input,
// moves, timings, determinism and LP_NUM_THREADS.
#include "gpu/driver_files.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu_test_support.hpp"
#include "support/catch.hpp"

#include <algorithm>
#include <cstdlib>
#include <iostream>

using namespace twinraster;
using namespace twinraster::gpu_test;

namespace {

const Rgb8 kBackground{1, 2, 3};
const Rgb8 kColour{90, 180, 45};

// One triangle that covers the whole clip square, so every pixel of any size gets kColour.
DrawList Covering(std::uint32_t width, std::uint32_t height) {
  DrawMesh mesh;
  mesh.positions = {glm::vec3(-1, -1, 0.5f), glm::vec3(3, -1, 0.5f), glm::vec3(-1, 3, 0.5f)};
  mesh.triangles = {{0, 1, 2}};
  mesh.colours = {kColour};
  DrawList list;
  list.width = width;
  list.height = height;
  list.background = kBackground;
  list.meshes = {mesh};
  list.draws = {DrawCall{0, glm::mat4(1.0f)}};
  return list;
}

bool AllPixels(const Image& image, Rgb8 colour) {
  return CountColour(image, colour) == std::size_t{image.width} * image.height;
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

}  // namespace

TEST_CASE("Without options the renderer picks lavapipe, and a name picks a device", "[gpu]") {
  CHECK_THAT(gpu::GpuRenderer().DeviceName(), HasSubstring("llvmpipe"));
  CHECK_THAT(gpu::GpuRenderer(gpu::GpuOptions{.device = "LLVMPIPE"}).DeviceName(), HasSubstring("llvmpipe"));
  CHECK_THROWS_AS(gpu::GpuRenderer(gpu::GpuOptions{.device = "no such device"}), gpu::GpuUnavailable);
  CHECK_THROWS_WITH(gpu::GpuRenderer(gpu::GpuOptions{.device = "no such device"}),
                    HasSubstring("no such device") && HasSubstring("llvmpipe"));
}

TEST_CASE("The default device loads lavapipe's driver alone, unless the user's loader variables choose", "[gpu]") {
  const auto driver_files = [] {
    const char* value = std::getenv("VK_DRIVER_FILES");
    return value ? std::string(value) : std::string("(unset)");
  };
  SECTION("nothing set: lavapipe's manifest alone, for the guard's lifetime") {
    {
      const gpu::LavapipeAlone alone;
      CHECK_THAT(alone.manifest(), HasSubstring("/vulkan/icd.d/lvp_icd.") && Catch::Matchers::EndsWith(".json"));
      CHECK(driver_files() == alone.manifest());
    }
    CHECK(driver_files() == "(unset)");
    CHECK_THAT(gpu::GpuRenderer().DeviceName(), HasSubstring("llvmpipe"));
  }
  SECTION("the user's choice stands") {
    for (const char* variable : {"VK_LOADER_DRIVERS_SELECT", "VK_LOADER_DRIVERS_DISABLE", "VK_ICD_FILENAMES",
                                 "VK_DRIVER_FILES", "VK_ADD_DRIVER_FILES"}) {
      INFO(variable);
      const ScopedEnv user(variable, "*lvp_icd*");
      const gpu::LavapipeAlone alone;
      CHECK(alone.manifest().empty());
      CHECK(driver_files() == (std::string(variable) == "VK_DRIVER_FILES" ? "*lvp_icd*" : "(unset)"));
    }
  }
  SECTION("no lavapipe for the loader to find: the default device is sought among every driver") {
    const ScopedEnv elsewhere("XDG_DATA_DIRS", "/nonexistent");
    CHECK(gpu::LavapipeAlone().manifest().empty());
  }
  SECTION("a device asked by name still finds the others") {
    CHECK_THAT(gpu::GpuRenderer(gpu::GpuOptions{.device = "swiftshader"}).DeviceName(), HasSubstring("SwiftShader"));
  }
}

TEST_CASE("GpuUnavailable says what to install", "[gpu][errors]") {
  // The loader's own variables hide the driver or the layer, as on a machine without them.
  SECTION("no Vulkan driver") {
    const ScopedEnv no_driver("VK_ICD_FILENAMES", "/nonexistent/no_icd.json");
    CHECK_THROWS_AS(gpu::GpuRenderer(), gpu::GpuUnavailable);
    CHECK_THROWS_WITH(gpu::GpuRenderer(), HasSubstring("apt-get install mesa-vulkan-drivers"));
  }
  SECTION("no validation layer") {
    const ScopedEnv no_layers("VK_LAYER_PATH", "/nonexistent");
    CHECK_NOTHROW(gpu::GpuRenderer());  // only validation needs the layer
    CHECK_THROWS_AS(gpu::GpuRenderer(gpu::GpuOptions{.device = "", .validation = true}), gpu::GpuUnavailable);
    CHECK_THROWS_WITH(gpu::GpuRenderer(gpu::GpuOptions{.device = "", .validation = true}),
                      HasSubstring("apt-get install vulkan-validationlayers"));
  }
}

TEST_CASE("Render takes any size from 1x1 to 16384 a side, and refuses others", "[gpu][sizes]") {
  gpu::GpuRenderer gpu;
  for (const auto& [width, height] : std::vector<std::pair<std::uint32_t, std::uint32_t>>{
           {1, 1}, {2, 3}, {16384, 1}, {1, 16384}, {600, 600}, {600, 600}, {5, 1}}) {
    INFO(width << "x" << height);
    const Image image = gpu.Render(Covering(width, height));
    REQUIRE(image.width == width);
    REQUIRE(image.height == height);
    REQUIRE(image.rgba.size() == std::size_t{width} * height * 4);
    CHECK(AllPixels(image, kColour));
  }
  for (const auto& [width, height] :
       std::vector<std::pair<std::uint32_t, std::uint32_t>>{{0, 1}, {1, 0}, {16385, 1}, {1, 16385}}) {
    INFO(width << "x" << height);
    CHECK_THROWS_AS(gpu.Render(Covering(width, height)), std::invalid_argument);
  }
  CHECK(AllPixels(gpu.Render(Covering(3, 3)), kColour));  // still usable
}

TEST_CASE("Render takes the largest image, 16384 x 16384", "[gpu][sizes]") {
  gpu::GpuRenderer gpu;
  DrawList list = Covering(16384, 16384);
  // The triangle now covers the top-left half only: pixels with x + y < 16383 (x + y = 16383
  // lies on its edge).
  list.meshes[0].positions[1].x = 1;
  list.meshes[0].positions[2].y = 1;
  const Image image = gpu.Render(list);
  REQUIRE(image.rgba.size() == std::size_t{16384} * 16384 * 4);
  CHECK(RgbAt(image, 0, 0) == kColour);
  CHECK(RgbAt(image, 16382, 0) == kColour);
  CHECK(RgbAt(image, 0, 16382) == kColour);
  CHECK(RgbAt(image, 8000, 8000) == kColour);
  CHECK(RgbAt(image, 16383, 1) == kBackground);
  CHECK(RgbAt(image, 16383, 16383) == kBackground);
  CHECK(RgbAt(image, 10000, 10000) == kBackground);
}

TEST_CASE("Malformed draw lists are refused before anything is drawn", "[gpu][errors]") {
  gpu::GpuRenderer gpu;
  DrawList list = Covering(4, 4);
  SECTION("a colour missing") { list.meshes[0].colours.clear(); }
  SECTION("an index past the vertices") { list.meshes[0].triangles[0][2] = 3; }
  SECTION("a draw of a missing mesh") { list.draws.push_back(DrawCall{1, glm::mat4(1.0f)}); }
  CHECK_THROWS_AS(gpu.Render(list), std::invalid_argument);
  CHECK(AllPixels(gpu.Render(Covering(4, 4)), kColour));  // the renderer is unharmed
}

TEST_CASE("Empty lists and meshes without triangles draw only the clear", "[gpu]") {
  gpu::GpuRenderer gpu;
  DrawList list = Covering(5, 4);
  SECTION("no draws") { list.draws.clear(); }
  SECTION("no meshes, no draws") {
    list.meshes.clear();
    list.draws.clear();
  }
  SECTION("a mesh without triangles, drawn twice") {
    DrawMesh one_vertex;
    one_vertex.positions = {glm::vec3(0, 0, 0)};
    list.meshes = {DrawMesh{}, one_vertex};
    list.draws = {DrawCall{0, glm::mat4(1.0f)}, DrawCall{1, glm::mat4(1.0f)}};
  }
  CHECK(AllPixels(gpu.Render(list), kBackground));
}

TEST_CASE("A moved renderer keeps working and the moved-from one refuses", "[gpu]") {
  gpu::GpuRenderer first;
  gpu::GpuRenderer second = std::move(first);
  CHECK(AllPixels(second.Render(Covering(3, 2)), kColour));
  CHECK_THROWS_AS(first.Render(Covering(3, 2)),
                  std::logic_error);  // NOLINT(bugprone-use-after-move)
  CHECK(first.DeviceName().empty());
  gpu::GpuRenderer third;
  third = std::move(second);
  CHECK(AllPixels(third.Render(Covering(2, 3)), kColour));
}

TEST_CASE("The chapter's two cubes at 600x600: deterministic, timed", "[gpu][timing]") {
  gpu::GpuRenderer gpu;
  const DrawList list = ChapterInstances(600, 600);
  REQUIRE(list.draws.size() == 2);
  const Image first = gpu.Render(list);
  std::vector<double> setup, draw, readback, total;
  for (int i = 0; i < 20; ++i) {
    gpu::GpuTimings timings;
    const Image again = gpu.Render(list, &timings);
    REQUIRE(again.rgba == first.rgba);
    CHECK(timings.draw_ms > 0);
    CHECK(timings.setup_ms >= 0);
    CHECK(timings.readback_ms >= 0);
    setup.push_back(timings.setup_ms);
    draw.push_back(timings.draw_ms);
    readback.push_back(timings.readback_ms);
    total.push_back(timings.setup_ms + timings.draw_ms + timings.readback_ms);
  }
  std::cout << "GPU (" << gpu.DeviceName() << ") 600x600 two cubes, median of 20: setup " << Median(setup)
            << " ms, draw " << Median(draw) << " ms, readback " << Median(readback) << " ms, total " << Median(total)
            << " ms\n";
  // What the chapter shows: both cubes' near faces (blue), the left cube's right face (green),
  // the right cube's bottom (cyan) and left (yellow) faces. Depth hides the far faces (red)
  // and the tops (purple).
  CHECK(CountColour(first, {0, 0, 255}) > 10000);
  CHECK(CountColour(first, {0, 255, 0}) > 1000);
  CHECK(CountColour(first, {0, 255, 255}) > 1000);
  CHECK(CountColour(first, {255, 255, 0}) > 500);
  CHECK(CountColour(first, {255, 0, 0}) == 0);
  CHECK(CountColour(first, {255, 0, 255}) == 0);               // the tops: the camera is not above either
  CHECK(CountColour(first, {255, 255, 255}) > 600 * 600 / 2);  // the canvas's white background
}

TEST_CASE("LP_NUM_THREADS=0 (rasterize on the calling thread) gives the same image", "[gpu]") {
  const DrawList list = ChapterInstances(301, 203);
  const Image threaded = gpu::GpuRenderer().Render(list);
  Image single;
  {
    const ScopedEnv no_threads("LP_NUM_THREADS", "0");
    single = gpu::GpuRenderer().Render(list);
  }
  CHECK(single.rgba == threaded.rgba);
  CHECK(CountColour(single, {0, 0, 255}) > 100);
}
