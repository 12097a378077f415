#include "twin_support.hpp"

#include "cpu/cpu_renderer.hpp"

#include <catch2/catch.hpp>

#include <sstream>

namespace twinraster::test {

namespace {
std::size_t g_messages_seen = 0;
}

GpuRenderer& SharedGpu() {
  static GpuRenderer renderer(GpuOptions{"", true});
  return renderer;
}

TwinResult RenderTwins(const DrawList& list) {
  TwinResult r;
  r.gpu = SharedGpu().Render(list);
  r.cpu = RenderOnCpu(list);
  r.comparison = CompareImages(r.gpu, r.cpu);
  return r;
}

std::string TwinResult::Describe() const {
  std::ostringstream s;
  s << gpu.width << " x " << gpu.height << ": " << comparison.differing_pixels << " differing pixels, max channel difference "
    << comparison.max_channel_difference;
  int shown = 0;
  for (std::uint32_t y = 0; y < gpu.height && shown < 8; ++y)
    for (std::uint32_t x = 0; x < gpu.width && shown < 8; ++x) {
      const std::uint8_t *g = gpu.pixel(x, y), *c = cpu.pixel(x, y);
      if (g[0] == c[0] && g[1] == c[1] && g[2] == c[2] && g[3] == c[3]) continue;
      s << "\n  pixel (" << x << ", " << y << "): gpu " << int(g[0]) << "," << int(g[1]) << "," << int(g[2])
        << "  cpu " << int(c[0]) << "," << int(c[1]) << "," << int(c[2]);
      ++shown;
    }
  return s.str();
}

void RequireNoValidationMessages() {
  const auto& messages = SharedGpu().ValidationMessages();
  std::string text;
  for (std::size_t i = g_messages_seen; i < messages.size(); ++i) text += messages[i] + "\n";
  g_messages_seen = messages.size();
  INFO(text);
  REQUIRE(text.empty());
}

}  // namespace twinraster::test
