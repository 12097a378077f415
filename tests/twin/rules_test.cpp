// The twin follows the rules of the lavapipe it is compared with: lavapipe drew on the path the run
// names, the row chosen for it draws what lavapipe draws, each of its rules flipped does not, and
// each rule changes pixels (so a rule left out would show).
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "named_path.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <string>

using namespace twinraster;

namespace {

// A rule, and a shipped scene whose pixels it changes.
struct RuleShown {
  const char* name;
  bool cpu::RasterRules::*rule;
  const char* scene;
  bool wireframe;
};
constexpr RuleShown kRulesShown[] = {
    {"fused multiply-add", &cpu::RasterRules::fused_multiply_add, "scenes/lit-mixed.json", false},
    {"triangles half away", &cpu::RasterRules::triangles_round_half_away, "scenes/catlike-grid.json", false},
    {"lines half to even", &cpu::RasterRules::lines_round_half_even, "scenes/tinyrenderer-style.json", true},
    {"wireframe guard band", &cpu::RasterRules::wireframe_guard_band, "scenes/hard/depth-ratio-1e-4.json", true},
};

Image RenderScene(const char* file, bool wireframe, const cpu::RasterRules& rules) {
  Scene s = LoadScene(test::SourcePath(file));
  s.wireframe = wireframe;
  return cpu::RenderOnCpu(BuildDrawList(s), cpu::CpuOptions{.rules = rules});
}

}  // namespace

TEST_CASE("The twin's rules are those of this device and CPU path", "[twin][rules]") {
  const twin_rules::TwinRules& twin = test::SharedTwinRules();
  INFO(twin.text);
  REQUIRE(twin.exact);
  // lavapipe really drew on the path the run names (the device and its pictures say so) ...
  test::RequireLavapipeOnNamedPath();
  // ... and every rule of the row chosen for it is the device's: the row draws what lavapipe
  // draws where that rule shows, and the row with that one rule flipped does not.
  int shown = 0;
  for (const RuleShown& r : kRulesShown) {
    INFO(r.name << " on " << r.scene << (r.wireframe ? " --wireframe" : ""));
    Scene s = LoadScene(test::SourcePath(r.scene));
    s.wireframe = r.wireframe;
    const Image gpu = test::SharedGpu().Render(BuildDrawList(s));
    cpu::RasterRules flipped = twin.rules;
    flipped.*r.rule = !(flipped.*r.rule);
    CHECK(CompareImages(gpu, RenderScene(r.scene, r.wireframe, twin.rules)).Equal());
    CHECK_FALSE(CompareImages(gpu, RenderScene(r.scene, r.wireframe, flipped)).Equal());
    ++shown;
  }
  CHECK(shown == 4);
}

TEST_CASE("Each rule the twin follows changes pixels of a shipped scene", "[twin][rules]") {
  int shown = 0;
  for (const RuleShown& r : kRulesShown) {
    INFO(r.name << " on " << r.scene << (r.wireframe ? " --wireframe" : ""));
    const cpu::RasterRules mesa22{};
    cpu::RasterRules flipped = mesa22;
    flipped.*r.rule = !(flipped.*r.rule);
    CHECK(CompareImages(RenderScene(r.scene, r.wireframe, mesa22), RenderScene(r.scene, r.wireframe, flipped))
              .differing_pixels > 0);
    ++shown;
  }
  CHECK(shown == 4);
}
