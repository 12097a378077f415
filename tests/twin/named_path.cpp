#include "named_path.hpp"

#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>
#include <string>

namespace twinraster::test {
namespace {

enum class Arithmetic { kFused, kSeparate, kX87 };

struct NamedPath {
  std::string name;
  Arithmetic arithmetic;
  int vector_bits;
};

std::string Variable(const char* name) {
  const char* value = std::getenv(name);
  return value != nullptr ? value : "";
}

// The CPU features the kernel reports ("flags" on x86-64, "Features" on aarch64).
std::set<std::string> CpuinfoFlags() {
  std::ifstream in("/proc/cpuinfo");
  std::set<std::string> flags;
  for (std::string line; std::getline(in, line);) {
    if (line.starts_with("flags") || line.starts_with("Features")) {
      std::istringstream words(line.substr(line.find(':') + 1));
      for (std::string word; words >> word;) flags.insert(word);
      break;
    }
  }
  return flags;
}

// What Mesa does with the variables (docs/lavapipe-paths.md): nosse leaves x87 arithmetic and
// 128-bit vectors; sse4.1 clears AVX, and FMA with it; avx clears only AVX-512.
NamedPath PathThisRunNames() {
  const std::string caps = Variable("GALLIUM_OVERRIDE_CPU_CAPS");
  const std::string width = Variable("LP_NATIVE_VECTOR_WIDTH");
  NamedPath path{"", Arithmetic::kFused, 0};
#if defined(__aarch64__)
  path = {"aarch64", Arithmetic::kFused, 128};
#else
  const std::set<std::string> flags = CpuinfoFlags();
  const bool avx = flags.contains("avx"), fma = flags.contains("fma");
  if (caps == "nosse") {
    path = {"nosse", Arithmetic::kX87, 128};
  } else if (caps == "sse4.1") {
    path = {"sse4.1", Arithmetic::kSeparate, 128};
  } else if (caps.empty() || caps == "avx") {
    path = {caps.empty() ? "this CPU's own" : "avx", avx && fma ? Arithmetic::kFused : Arithmetic::kSeparate,
            avx ? 256 : 128};
  } else {
    FAIL("no expected path written for GALLIUM_OVERRIDE_CPU_CAPS=" << caps);
  }
#endif
  if (!width.empty()) path.vector_bits = std::stoi(width);
  return path;
}

}  // namespace

void RequireLavapipeOnNamedPath() {
  const NamedPath path = PathThisRunNames();
  const gpu::DeviceIdentity& device = SharedGpu().Device();
  INFO("the " << path.name << " path; device " << device.name << " (" << device.driver_info << ")");
  REQUIRE(device.name.find(", " + std::to_string(path.vector_bits) + " bits)") != std::string::npos);

  // The twin's rules for this device, or its defaults where it has none (nosse), with FMA on or off.
  cpu::RasterRules fused = SharedTwinRules().exact ? SharedTwinRules().rules : cpu::RasterRules{};
  fused.fused_multiply_add = true;
  cpu::RasterRules separate = fused;
  separate.fused_multiply_add = false;
  // Scenes where the three arithmetics give different pixels (rules_test.cpp, docs/lavapipe-paths.md).
  int scenes = 0, like_fused = 0, like_separate = 0;
  for (const char* file : {"scenes/lit-mixed.json", "scenes/catlike-grid.json"}) {
    const DrawList list = BuildDrawList(LoadScene(SourcePath(file)));
    const Image gpu = SharedGpu().Render(list);
    like_fused += CompareImages(gpu, cpu::RenderOnCpu(list, cpu::CpuOptions{.rules = fused})).Equal();
    like_separate += CompareImages(gpu, cpu::RenderOnCpu(list, cpu::CpuOptions{.rules = separate})).Equal();
    ++scenes;
  }
  INFO(like_fused << " of " << scenes << " scenes as the twin draws them fused, " << like_separate << " separate");
  REQUIRE(scenes == 2);
  switch (path.arithmetic) {
    case Arithmetic::kFused:
      CHECK(like_fused == scenes);
      CHECK(like_separate < scenes);
      break;
    case Arithmetic::kSeparate:
      CHECK(like_separate == scenes);
      CHECK(like_fused < scenes);
      break;
    case Arithmetic::kX87:
      CHECK(like_fused < scenes);
      CHECK(like_separate < scenes);
      break;
  }
}

}  // namespace twinraster::test
