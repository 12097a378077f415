// Per-draw push constants and instanced drawing give the same pixels as each other and as the CPU
// twin, including where equal depths make draw order decide, and across instance buffers.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "support/catch.hpp"
#include "support/chapter_cube.hpp"
#include "twin_support.hpp"

#include <algorithm>

using namespace twinraster;

namespace {

// A grid of cubes of alternating colours where every second cube sits exactly where the one
// before it is: same depth everywhere, so only draw order decides which colour shows.
DrawList CoincidentCubes() {
  Scene scene;
  scene.canvas = Canvas{97, 61, Rgb8{20, 20, 20}};
  scene.viewport = Viewport{1.6, 1.0, 1.0};
  scene.models = {test::ChapterCube(), test::ChapterCube()};
  for (auto& t : scene.models[1].triangles) t.colour = Rgb8{250, 250, 250};
  for (int i = 0; i < 40; ++i) {
    Instance a;
    a.model = static_cast<std::size_t>(i / 20);  // runs of 20 of mesh 0, then of mesh 1
    a.transform.scale = glm::dvec3(0.3);
    a.transform.translation = glm::dvec3(-2.5 + 0.5 * (i % 10), -1.0 + 0.5 * ((i / 10) % 2), 6.0 + (i % 3));
    scene.instances.push_back(a);
    scene.instances.push_back(a);  // its twin, coincident
  }
  return BuildDrawList(scene);
}

// Thirty instances of one two-triangle mesh, overlapping in one plane facing the camera: every
// overlap is at exactly equal depth, so each pixel shows the first triangle drawn there, first
// by instance order and then, within an instance, by triangle order.
DrawList OverlappingPlanes() {
  Scene scene;
  scene.canvas = Canvas{80, 64, Rgb8{0, 0, 0}};
  scene.viewport = Viewport{1.25, 1.0, 1.0};
  Model m;
  m.name = "two";
  m.vertices = {glm::dvec3(0, 0, 0), glm::dvec3(1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(1, 1, 0)};
  m.triangles = {{{0, 1, 2}, Rgb8{255, 0, 0}}, {{0, 1, 3}, Rgb8{0, 0, 255}}};
  scene.models = {m};
  for (int i = 0; i < 30; ++i) {
    Instance a;
    a.transform.translation = glm::dvec3(-2.0 + 0.11 * i, -1.5 + 0.07 * i, 5.0);
    scene.instances.push_back(a);
  }
  return BuildDrawList(scene);
}

}  // namespace

TEST_CASE("Equal depths: instanced draws keep instance order, then triangle order", "[twin][instancing]") {
  const DrawList list = OverlappingPlanes();
  const test::TwinResult r = test::RenderTwins(list);
  INFO(r.Describe());
  REQUIRE(r.Equal());
  // The test means something only if both colours show.
  std::size_t red = 0, blue = 0;
  for (std::size_t i = 0; i < r.cpu.rgba.size(); i += 4) red += r.cpu.rgba[i] == 255, blue += r.cpu.rgba[i + 2] == 255;
  REQUIRE(red > 100);
  REQUIRE(blue > 100);
  // Drawn in reverse instance order the picture changes: the order is what the test checks.
  DrawList reversed = list;
  std::reverse(reversed.draws.begin(), reversed.draws.end());
  REQUIRE_FALSE(CompareImages(cpu::RenderOnCpu(reversed, test::TwinOptions()), r.cpu).Equal());
  test::RequireNoValidationMessages();
}

TEST_CASE("Instanced and per-draw F give identical pixels, with ties and split buffers", "[twin][instancing]") {
  const DrawList list = CoincidentCubes();
  const Image cpu = cpu::RenderOnCpu(list, test::TwinOptions());
  gpu::GpuRenderer split(gpu::GpuOptions{
      .device = "", .validation = true, .instancing = gpu::Instancing::kAlways, .instances_per_buffer = 7});
  gpu::GpuTimings timings;
  const Image gpu_split = split.Render(list, &timings);
  INFO(CompareImages(gpu_split, cpu).differing_pixels << " pixels differ with buffers of 7");
  REQUIRE(CompareImages(gpu_split, cpu).Equal());
  REQUIRE(timings.instanced_draws == list.draws.size());
  REQUIRE(timings.draw_commands > 80 / 7);  // at least one draw per buffer
  REQUIRE(timings.draw_commands < list.draws.size());
  REQUIRE(split.ValidationMessages().empty());

  const test::TwinResult r = test::RenderTwins(list);
  INFO(r.Describe());
  REQUIRE(r.Equal());
  test::RequireNoValidationMessages();
}

TEST_CASE("kAuto instances long runs only, and still matches the twin", "[twin][instancing]") {
  const DrawList list = CoincidentCubes();  // runs of 40 draws of one mesh: instanced under kAuto
  gpu::GpuRenderer automatic(gpu::GpuOptions{.device = "", .validation = true});
  gpu::GpuTimings timings;
  const Image image = automatic.Render(list, &timings);
  REQUIRE(timings.instanced_draws == list.draws.size());
  REQUIRE(timings.draw_commands == 2);
  REQUIRE(CompareImages(image, cpu::RenderOnCpu(list, test::TwinOptions())).Equal());
  REQUIRE(automatic.ValidationMessages().empty());
}
