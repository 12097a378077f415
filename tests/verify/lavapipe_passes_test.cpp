// Lavapipe passes the verifier: 0 violations on every shipped scene, filled and in wireframe, lit
// or not, on lavapipe itself and (since the twin is bit-exact with each, docs/lavapipe-paths.md)
// under every release's and CPU path's rules on 500 random scenes.
#include "../twin/named_path.hpp"
#include "../twin/twin_support.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "run_report/verify_report.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "twin_rules/twin_rules.hpp"
#include "verify/verifier.hpp"
#include "verify_scenes.hpp"

#include <algorithm>
#include <filesystem>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

constexpr std::uint32_t kRandomScenes = 500;
// Mesa 22.3.6 with and without FMA, on aarch64; Mesa 25.0.7 with and without FMA.
constexpr std::size_t kDistinctRuleSets = 5;

// The distinct rule sets of the twin's own table of lavapipes (twin_rules/twin_rules.cpp), each once and
// named by its first row: a row added there is judged here with no edit.
struct NamedRules {
  std::string name;
  cpu::RasterRules rules;
};
std::vector<NamedRules> LavapipeRules() {
  std::vector<NamedRules> distinct;
  for (const twin_rules::KnownLavapipe& known : twin_rules::KnownLavapipes()) {
    const bool seen =
        std::any_of(distinct.begin(), distinct.end(), [&](const NamedRules& r) { return r.rules == known.rules; });
    if (!seen) {
      distinct.push_back({"Mesa " + std::string(known.mesa) + ", " + std::string(known.instruction_set) + " " +
                              std::to_string(known.vector_bits) + "-bit",
                          known.rules});
    }
  }
  return distinct;
}

// Judged by the device's own rules: lavapipe reports strictLines, and the twin draws its lines.
void RequirePasses(const Scene& scene, const DrawList& list, const Image& image, int bits, const std::string& what) {
  const verify::Verification v = verify::VerifyImage(scene, list, image, {.subpixel_bits = bits, .strict_lines = true});
  INFO(what << ": " << run_report::VerificationText(v));
  CHECK(v.NoViolations());
}

}  // namespace

TEST_CASE("Lavapipe's image of every shipped scene, filled and in wireframe, passes at the device's subpixel bits",
          "[verify][gpu]") {
  gpu::GpuRenderer& gpu = test::SharedGpu();
  const int bits = int(gpu.Device().subpixel_bits);
  REQUIRE(bits >= 4);
  REQUIRE(gpu.Device().strict_lines);
  test::RequireLavapipeOnNamedPath();  // run again on other paths (tests/verify/CMakeLists.txt)
  int judged = 0;
  for (const auto& file : test::ShippedScenesAndMeshes()) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::ShippedScene(file, wireframe);
      RequirePasses(d.scene, d.list, gpu.Render(d.list), bits, file.string() + (wireframe ? " --wireframe" : ""));
      ++judged;
    }
  }
  CHECK(judged == static_cast<int>(2 * test::ShippedScenesAndMeshes().size()));
  test::RequireNoValidationMessages();
}

TEST_CASE("500 random scenes drawn by lavapipe pass, filled and in wireframe", "[verify][gpu][random]") {
  gpu::GpuRenderer& gpu = test::SharedGpu();
  const int bits = int(gpu.Device().subpixel_bits);
  for (std::uint32_t seed = 1; seed <= kRandomScenes; ++seed) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::RandomScene(seed, wireframe);
      RequirePasses(d.scene, d.list, gpu.Render(d.list), bits,
                    "seed " + std::to_string(seed) + (wireframe ? " --wireframe" : ""));
    }
  }
  test::RequireNoValidationMessages();
}

TEST_CASE("500 random scenes under every lavapipe release's and path's rules pass, filled and in wireframe",
          "[verify][random]") {
  const std::vector<NamedRules> rule_sets = LavapipeRules();
  REQUIRE(rule_sets.size() == kDistinctRuleSets);
  for (std::uint32_t seed = 1; seed <= kRandomScenes; ++seed) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::RandomScene(seed, wireframe);
      for (const NamedRules& r : rule_sets) {
        cpu::CpuOptions options;
        options.rules = r.rules;
        RequirePasses(d.scene, d.list, cpu::RenderOnCpu(d.list, options), 8,
                      std::string(r.name) + ", seed " + std::to_string(seed) + (wireframe ? " --wireframe" : ""));
      }
    }
  }
}

TEST_CASE("Every shipped scene under every lavapipe release's and path's rules passes, filled and in wireframe",
          "[verify]") {
  const std::vector<NamedRules> rule_sets = LavapipeRules();
  REQUIRE(rule_sets.size() == kDistinctRuleSets);
  int judged = 0;
  for (const auto& file : test::ShippedScenesAndMeshes()) {
    for (const bool wireframe : {false, true}) {
      const test::Drawn d = test::ShippedScene(file, wireframe);
      for (const NamedRules& r : rule_sets) {
        cpu::CpuOptions options;
        options.rules = r.rules;
        RequirePasses(d.scene, d.list, cpu::RenderOnCpu(d.list, options), 8,
                      std::string(r.name) + ": " + file.string() + (wireframe ? " --wireframe" : ""));
        ++judged;
      }
    }
  }
  CHECK(judged == static_cast<int>(2 * test::ShippedScenesAndMeshes().size() * kDistinctRuleSets));
}
