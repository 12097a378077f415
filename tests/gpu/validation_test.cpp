// With VK_LAYER_KHRONOS_validation and synchronization validation on, the renderer's use of
// Vulkan draws no complaint, and the messenger demonstrably records complaints when there are some.
#include "gpu/gpu_renderer.hpp"
#include "gpu_test_support.hpp"
#include "support/catch.hpp"

using namespace twinraster;
using namespace twinraster::gpu_test;

namespace {

void RequireSilence(const gpu::GpuRenderer& gpu, const char* after) {
  INFO("after " << after);
  for (const std::string& message : gpu.ValidationMessages()) UNSCOPED_INFO(message);
  REQUIRE(gpu.ValidationMessages().empty());
}

DrawList OneTriangle(std::uint32_t width, std::uint32_t height) {
  DrawList list;
  list.width = width;
  list.height = height;
  list.background = Rgb8{40, 50, 60};
  // push_back, not `= {...}`: GCC 14 (Debian 13) sees a false -Warray-bounds in that copy.
  list.meshes.push_back(MeshOf({{{1, 1}, {7, 1}, {1, 6}, {200, 100, 50}}}, 8, 8));
  list.draws = {DrawCall{0, glm::mat4(1.0f)}};
  return list;
}

}  // namespace

TEST_CASE("Validation stays silent through construction and several renders", "[gpu][validation]") {
  gpu::GpuRenderer gpu(gpu::GpuOptions{.device = "", .validation = true});
  RequireSilence(gpu, "construction");

  const Image triangle = gpu.Render(OneTriangle(8, 8));
  RequireSilence(gpu, "one triangle, 8x8");
  CHECK(CountColour(triangle, {200, 100, 50}) == 15);

  const Image cubes = gpu.Render(ChapterInstances(600, 600));
  RequireSilence(gpu, "two cube instances, 600x600");
  CHECK(CountColour(cubes, {0, 0, 255}) > 1000);  // the cubes' near faces are blue

  // The same size again reuses the images: the render pass's external dependency must order
  // this frame's clears after the previous frame's copy and depth writes.
  gpu.Render(ChapterInstances(600, 600));
  RequireSilence(gpu, "the same list again");

  DrawList empty;
  empty.width = 37;
  empty.height = 23;
  const Image cleared = gpu.Render(empty);
  RequireSilence(gpu, "an empty list, 37x23");
  CHECK(CountColour(cleared, {0, 0, 0}) == 37 * 23);

  gpu.Render(ChapterInstances(37, 23));
  RequireSilence(gpu, "two cube instances, 37x23");

  DrawList no_triangles = OneTriangle(8, 8);
  no_triangles.meshes.push_back(DrawMesh{});
  no_triangles.draws = {DrawCall{1, glm::mat4(1.0f)}, DrawCall{0, glm::mat4(1.0f)}};
  gpu.Render(no_triangles);
  RequireSilence(gpu, "a mesh without triangles");
}

TEST_CASE("The messenger records what the layer reports (silence is not deafness)", "[gpu][validation]") {
  // Best-practices checks, switched on through the layer's environment variable, warn about
  // legal but questionable use (tiny allocations, old API version, ...). Seeing those warnings
  // in ValidationMessages() shows that the messenger would catch real errors too.
  std::vector<std::string> messages;
  {
    const ScopedEnv best_practices("VK_LAYER_ENABLES", "VK_VALIDATION_FEATURE_ENABLE_BEST_PRACTICES_EXT");
    gpu::GpuRenderer gpu(gpu::GpuOptions{.device = "", .validation = true});
    gpu.Render(OneTriangle(8, 8));
    messages = gpu.ValidationMessages();
  }
  for (const std::string& message : messages) UNSCOPED_INFO(message);
  CHECK_FALSE(messages.empty());

  // Without validation nothing is collected, whatever the layer setting.
  gpu::GpuRenderer quiet;
  quiet.Render(OneTriangle(8, 8));
  CHECK(quiet.ValidationMessages().empty());
}
