// Lavapipe passes the verifier: 0 violations on every shipped scene, filled and in wireframe, lit
// or not, on lavapipe itself and (since the twin is bit-exact with each, docs/lavapipe-paths.md)
// under every release's and CPU path's rules on 500 random scenes.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "support/test_support.hpp"
#include "verify/verifier.hpp"

#include "../twin/twin_support.hpp"
#include "verify_scenes.hpp"

#include "support/catch.hpp"

#include <array>
#include <filesystem>

using namespace twinraster;

namespace {

constexpr std::uint32_t kRandomScenes = 500;

// The rule sets of the twin's table of lavapipes (cpu/twin_rules.cpp), each once.
struct NamedRules {
  const char* name;
  cpu::RasterRules rules;
};
const std::array kLavapipeRules = {
    NamedRules{"Mesa 22.3.6, FMA (AVX2, or 128-bit)", {.fused_multiply_add = true}},
    NamedRules{"Mesa 22.3.6, sse4.1", {.fused_multiply_add = false}},
    NamedRules{"Mesa 22.3.6, aarch64", {.fused_multiply_add = true, .triangles_round_half_away = true}},
    NamedRules{"Mesa 25.0.7, FMA", {.fused_multiply_add = true, .lines_round_half_even = true, .wireframe_guard_band = true}},
    NamedRules{"Mesa 25.0.7, sse4.1", {.fused_multiply_add = false, .lines_round_half_even = true, .wireframe_guard_band = true}},
};

// Judged by the device's own rules: lavapipe reports strictLines, and the twin draws its lines.
void RequirePasses(const Scene& scene, const DrawList& list, const Image& image, int bits, const std::string& what) {
  const verify::Verification v = verify::VerifyImage(scene, list, image, {.subpixel_bits = bits, .strict_lines = true});
  INFO(what << ": " << verify::VerificationText(v));
  CHECK(v.NoViolations());
}

}  // namespace

TEST_CASE("Lavapipe's image of every shipped scene, filled and in wireframe, passes at the device's subpixel bits",
          "[verify][gpu]") {
  GpuRenderer& gpu = test::SharedGpu();
  const int bits = int(gpu.Device().subpixel_bits);
  REQUIRE(bits >= 4);
  REQUIRE(gpu.Device().strict_lines);
  int judged = 0;
  for (const auto& file : test::ShippedScenesAndMeshes()) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::ShippedScene(file, wireframe);
      RequirePasses(d.scene, d.list, gpu.Render(d.list), bits, file.string() + (wireframe ? " --wireframe" : ""));
      ++judged;
    }
  }
  CHECK(judged >= 90);
  test::RequireNoValidationMessages();
}

TEST_CASE("500 random scenes drawn by lavapipe pass, filled and in wireframe", "[verify][gpu][random]") {
  GpuRenderer& gpu = test::SharedGpu();
  const int bits = int(gpu.Device().subpixel_bits);
  for (std::uint32_t seed = 1; seed <= kRandomScenes; ++seed) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::RandomScene(seed, wireframe);
      RequirePasses(d.scene, d.list, gpu.Render(d.list), bits, "seed " + std::to_string(seed) + (wireframe ? " --wireframe" : ""));
    }
  }
  test::RequireNoValidationMessages();
}

TEST_CASE("500 random scenes under every lavapipe release's and path's rules pass, filled and in wireframe",
          "[verify][random]") {
  for (std::uint32_t seed = 1; seed <= kRandomScenes; ++seed) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::RandomScene(seed, wireframe);
      for (const NamedRules& r : kLavapipeRules) {
        CpuOptions options;
        options.rules = r.rules;
        RequirePasses(d.scene, d.list, RenderOnCpu(d.list, options), 8,
                      std::string(r.name) + ", seed " + std::to_string(seed) + (wireframe ? " --wireframe" : ""));
      }
    }
  }
}

TEST_CASE("Every shipped scene under every lavapipe release's and path's rules passes, filled and in wireframe",
          "[verify]") {
  for (const auto& file : test::ShippedScenesAndMeshes()) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::ShippedScene(file, wireframe);
      for (const NamedRules& r : kLavapipeRules) {
        CpuOptions options;
        options.rules = r.rules;
        RequirePasses(d.scene, d.list, RenderOnCpu(d.list, options), 8,
                      std::string(r.name) + ": " + file.string() + (wireframe ? " --wireframe" : ""));
      }
    }
  }
}
