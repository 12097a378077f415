// Every shipped scene renders identically on lavapipe and on the CPU twin: 0 differing pixels.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

using namespace twinraster;

TEST_CASE("Every shipped scene, filled and in wireframe: GPU image == CPU image, bit for bit", "[twin]") {
  std::size_t judged = 0;
  for (const auto& file : test::ShippedScenes()) {
    for (const bool wireframe : {false, true}) {
      INFO(file.string() << (wireframe ? " --wireframe" : ""));
      Scene scene = LoadScene(file);
      scene.wireframe = scene.wireframe || wireframe;
      const test::TwinResult r = test::RenderTwins(BuildDrawList(scene));
      INFO(r.Describe());
      REQUIRE(r.Equal());
      // Not a blank image: the scene drew something besides the background.
      REQUIRE(test::CountNotColour(r.cpu, scene.canvas.background) > 100);
      ++judged;
    }
  }
  CHECK(judged == 2 * 46);  // test::ShippedScenes() checks there are 46
  test::RequireNoValidationMessages();
}

TEST_CASE("The million-instance scenes at 480x270, filled and in wireframe: GPU (instanced) == CPU", "[twin][large]") {
  for (const auto& file : test::LargeShippedScenes()) {
    INFO(file.string());
    Scene scene = LoadScene(file);
    REQUIRE(scene.instances.size() >= 1'000'000);
    // A smaller canvas with the same field of view: the same geometry, a sixteenth of the pixels.
    scene.canvas.width = 480;
    scene.canvas.height = 270;
    gpu::GpuRenderer gpu(gpu::GpuOptions{.device = "", .validation = true});  // kAuto: the path a user gets
    for (const bool wireframe : {false, true}) {
      INFO((wireframe ? "wireframe" : "filled"));
      scene.wireframe = wireframe;
      const DrawList list = BuildDrawList(scene);
      gpu::GpuTimings timings;
      const Image gpu_image = gpu.Render(list, &timings);
      REQUIRE(timings.instanced_draws == list.draws.size());
      const Image cpu_image = cpu::RenderOnCpu(list, test::TwinOptions());
      const Comparison c = CompareImages(gpu_image, cpu_image);
      INFO(c.differing_pixels << " differing pixels");
      REQUIRE(c.Equal());
    }
    REQUIRE(gpu.ValidationMessages().empty());
  }
}
