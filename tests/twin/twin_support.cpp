#include "twin_support.hpp"

#include "cpu/cpu_renderer.hpp"
#include "run/backend_draws.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <memory>
#include <sstream>
#include <stdexcept>

namespace twinraster::test {

namespace {
std::size_t g_messages_seen[2] = {0, 0};  // per shared renderer
}

gpu::GpuRenderer& SharedGpu(gpu::Instancing instancing) {
  // Destroyed when the run ends, before main returns: on Debian 13 (Mesa 25.0.7, validation layer
  // 1.4.309) destroying them from a static destructor crashes the process after every test has
  // passed (the driver's own exit handlers have run by then), and never destroying them leaves
  // lavapipe's allocations to LeakSanitizer.
  static std::unique_ptr<gpu::GpuRenderer> per_draw, instanced;
  if (instancing == gpu::Instancing::kAuto) throw std::logic_error("SharedGpu: choose a path");
  std::unique_ptr<gpu::GpuRenderer>& renderer = instancing == gpu::Instancing::kAlways ? instanced : per_draw;
  if (!renderer) {
    renderer =
        std::make_unique<gpu::GpuRenderer>(gpu::GpuOptions{.device = "", .validation = true, .instancing = instancing});
    AtEndOfRun([&renderer] { renderer.reset(); });
  }
  return *renderer;
}

gpu::GpuRenderer& SharedSwiftShader() {
  static std::unique_ptr<gpu::GpuRenderer> gpu;
  if (!gpu) {
    gpu = std::make_unique<gpu::GpuRenderer>(gpu::GpuOptions{.device = "SwiftShader", .validation = true});
    AtEndOfRun([] { gpu.reset(); });
  }
  return *gpu;
}

const twin_rules::TwinRules& SharedTwinRules() {
  static const twin_rules::TwinRules rules = [] {
    const gpu::DeviceIdentity& device = SharedGpu().Device();
    return twin_rules::ChooseTwinRules(run::FactsOf(device), twin_rules::DetectCpuPath());
  }();
  return rules;
}

cpu::CpuOptions TwinOptions(cpu::CpuOptions options) {
  const twin_rules::TwinRules& twin = SharedTwinRules();
  if (!twin.exact) throw std::runtime_error("the twin cannot be compared here: " + twin.text);
  options.rules = twin.rules;
  return options;
}

TwinResult RenderTwins(const DrawList& list) {
  TwinResult r;
  r.gpu = SharedGpu(gpu::Instancing::kNever).Render(list);
  r.gpu_instanced = SharedGpu(gpu::Instancing::kAlways).Render(list);
  r.cpu = cpu::RenderOnCpu(list, TwinOptions());
  // Again in chunks of 24 triangles, so the depth tiles are refreshed (and skip hidden triangles)
  // between chunks even in a small scene: that must change nothing.
  if (cpu::RenderOnCpu(list, TwinOptions(cpu::CpuOptions{.chunk_triangles = 24})).rgba != r.cpu.rgba) {
    throw std::runtime_error("the twin's image changed when rendered in chunks of 24 triangles");
  }
  r.comparison = CompareImages(r.gpu, r.cpu);
  r.instanced_comparison = CompareImages(r.gpu_instanced, r.cpu);
  return r;
}

namespace {
void DescribeDifference(std::ostringstream& s, const char* name, const Image& gpu, const Image& cpu,
                        const Comparison& comparison) {
  s << name << " " << gpu.width << " x " << gpu.height << ": " << comparison.differing_pixels
    << " differing pixels, max channel difference " << comparison.max_channel_difference;
  int shown = 0;
  for (std::uint32_t y = 0; y < gpu.height && shown < 8; ++y)
    for (std::uint32_t x = 0; x < gpu.width && shown < 8; ++x) {
      const std::uint8_t *g = gpu.pixel(x, y), *c = cpu.pixel(x, y);
      if (g[0] == c[0] && g[1] == c[1] && g[2] == c[2] && g[3] == c[3]) continue;
      s << "\n  pixel (" << x << ", " << y << "): gpu " << int(g[0]) << "," << int(g[1]) << "," << int(g[2]) << "  cpu "
        << int(c[0]) << "," << int(c[1]) << "," << int(c[2]);
      ++shown;
    }
  s << "\n";
}
}  // namespace

std::string TwinResult::Describe() const {
  std::ostringstream s;
  DescribeDifference(s, "per-draw F:", gpu, cpu, comparison);
  DescribeDifference(s, "instanced F:", gpu_instanced, cpu, instanced_comparison);
  return s.str();
}

void RequireNoValidationMessages() {
  std::string text;
  for (const gpu::Instancing path : {gpu::Instancing::kNever, gpu::Instancing::kAlways}) {
    const auto& messages = SharedGpu(path).ValidationMessages();
    std::size_t& seen = g_messages_seen[path == gpu::Instancing::kAlways ? 1 : 0];
    for (std::size_t i = seen; i < messages.size(); ++i) text += messages[i] + "\n";
    seen = messages.size();
  }
  INFO(text);
  REQUIRE(text.empty());
}

}  // namespace twinraster::test
