// The GPU process: the same pixels as drawing in this process, the device named, and a driver
// that aborts, hangs or refuses a list reported as such while this process goes on.
#include "gpu/isolated_gpu.hpp"

#include "gpu/gpu_renderer.hpp"
#include "gpu_test_support.hpp"
#include "support/catch.hpp"
#include "support/lit_scene.hpp"

#include <chrono>
#include <stdexcept>

using namespace twinraster;
using namespace twinraster::gpu_test;

TEST_CASE("A list drawn in the GPU process gives the pixels drawn in this one, and names the device") {
  const DrawList list = ChapterInstances(160, 120);
  const gpu::IsolatedGpuResult isolated = gpu::RenderIsolated(list, {});
  REQUIRE(isolated.outcome == gpu::GpuOutcome::kRendered);
  CHECK(isolated.problem.empty());
  gpu::GpuRenderer renderer;
  const Image here = renderer.Render(list);
  CHECK(isolated.image.width == 160);
  CHECK(isolated.image.height == 120);
  CHECK(isolated.image.rgba == here.rgba);
  CHECK(isolated.device.name == renderer.Device().name);
  CHECK(isolated.device.driver_info == renderer.Device().driver_info);
  CHECK(isolated.device_ms > 0);
  CHECK(isolated.timings.draw_commands > 0);
}

TEST_CASE("A GPU process that aborts is a crash named by its signal, with the device it had") {
  const ScopedEnv fault("TWINRASTER_TEST_GPU_FAULT", "abort");
  const gpu::IsolatedGpuResult r = gpu::RenderIsolated(ChapterInstances(64, 48), {});
  CHECK(r.outcome == gpu::GpuOutcome::kCrashed);
  CHECK(r.signal == "SIGABRT");
  CHECK(r.problem == "the Vulkan driver crashed (SIGABRT)");
  CHECK_FALSE(r.device.name.empty());  // it died after it had its device, while drawing
  CHECK(r.image.rgba.empty());
}

TEST_CASE("A GPU process that hangs is stopped at the time limit") {
  const ScopedEnv fault("TWINRASTER_TEST_GPU_FAULT", "hang");
  gpu::IsolationOptions options;
  options.timeout_seconds = 0.5;
  const auto start = std::chrono::steady_clock::now();
  const gpu::IsolatedGpuResult r = gpu::RenderIsolated(ChapterInstances(64, 48), options);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  CHECK(r.outcome == gpu::GpuOutcome::kTimedOut);
  CHECK(r.problem == "timed out after 0.5 s");
  CHECK(seconds >= 0.5);
  CHECK(seconds < 30);  // killed, not waited for
}

TEST_CASE("A list the renderer refuses comes back as a bad list, with its reason") {
  DrawList list = ChapterInstances(64, 48);
  list.draws.front().mesh = 7;
  const gpu::IsolatedGpuResult r = gpu::RenderIsolated(list, {});
  CHECK(r.outcome == gpu::GpuOutcome::kBadList);
  CHECK_THAT(r.problem, HasSubstring("mesh"));
}

TEST_CASE("After a crashed GPU process the next one draws") {
  {
    const ScopedEnv fault("TWINRASTER_TEST_GPU_FAULT", "abort");
    REQUIRE(gpu::RenderIsolated(ChapterInstances(32, 24), {}).outcome == gpu::GpuOutcome::kCrashed);
  }
  CHECK(gpu::RenderIsolated(ChapterInstances(32, 24), {}).outcome == gpu::GpuOutcome::kRendered);
}

TEST_CASE("One GPU process draws a batch: later lists, lit or in wireframe, sent to it give the pixels drawn here") {
  DrawList lit = BuildDrawList(test::RandomLitScene(7));
  REQUIRE(lit.lighting.has_value());
  DrawList wire = ChapterInstances(90, 70);
  wire.wireframe = true;
  const std::vector<DrawList> lists = {ChapterInstances(160, 120), lit, wire, ChapterInstances(33, 17)};
  gpu::GpuProcess process({});
  gpu::GpuRenderer here;
  for (std::size_t i = 0; i < lists.size(); ++i) {
    INFO("list " << i);
    const gpu::IsolatedGpuResult r = process.Render(lists[i]);
    REQUIRE(r.outcome == gpu::GpuOutcome::kRendered);
    CHECK(r.image.rgba == here.Render(lists[i]).rgba);
    CHECK((r.device_ms > 0) == (i == 0));  // the device is made once
    CHECK(r.device.name == here.Device().name);
  }
}

TEST_CASE("Submit and Collect: the child draws while this process works, and knows its device from its first answer") {
  gpu::GpuProcess process({});
  gpu::GpuRenderer here;
  CHECK(process.device().name.empty());
  CHECK_THROWS_AS(process.Collect(), std::logic_error);  // nothing submitted
  for (const DrawList& list : {ChapterInstances(160, 120), ChapterInstances(64, 64)}) {
    process.Submit(list);
    CHECK_THROWS_AS(process.Submit(list), std::logic_error);  // one list at a time
    const Image meanwhile = here.Render(list);                // this process's own work
    const gpu::IsolatedGpuResult r = process.Collect();
    REQUIRE(r.outcome == gpu::GpuOutcome::kRendered);
    CHECK(r.image.rgba == meanwhile.rgba);
    CHECK(process.device().name == here.Device().name);
    CHECK(r.isolation_ms >= 0);
  }
}
