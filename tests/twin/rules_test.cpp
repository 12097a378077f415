// The twin follows the rules of the lavapipe it is compared with: chosen from the device and the
// CPU path as render chooses them, and each rule changes pixels (so a rule left out would show).
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include "support/catch.hpp"

#include <cstdlib>
#include <string>

using namespace twinraster;

TEST_CASE("The twin's rules are those of this device and CPU path", "[twin][rules]") {
  const cpu::TwinRules& twin = test::SharedTwinRules();
  INFO(twin.text);
  REQUIRE(twin.exact);
  REQUIRE(twin.release.has_value());
  const char* forced = std::getenv("GALLIUM_OVERRIDE_CPU_CAPS");
  const std::string path = forced != nullptr ? forced : "";
  CHECK(twin.path.override_caps == path);
  if (path == "sse4.1") {
    // Mesa's sse4.1 path clears AVX, so FMA and 256-bit vectors go with it.
    CHECK(twin.path.InstructionSet() == "SSE4.1");
    CHECK(twin.release->vector_bits == 128);
    CHECK_FALSE(twin.rules.fused_multiply_add);
  }
  CHECK(twin.text.find("lavapipe rules, Mesa " + twin.release->mesa) == 0);
}

TEST_CASE("Each rule the twin follows changes pixels of a shipped scene", "[twin][rules]") {
  const auto render = [](const char* scene, bool wireframe, const cpu::RasterRules& rules) {
    Scene s = LoadScene(test::SourcePath(scene));
    s.wireframe = wireframe;
    return RenderOnCpu(BuildDrawList(s), CpuOptions{.rules = rules});
  };
  const cpu::RasterRules mesa22{};
  SECTION("fused multiply-add: the sse4.1 path's separate roundings") {
    const Image fused = render("scenes/lit-mixed.json", false, mesa22);
    const Image separate = render("scenes/lit-mixed.json", false, cpu::RasterRules{.fused_multiply_add = false});
    CHECK(CompareImages(fused, separate).differing_pixels > 0);
  }
  SECTION("aarch64's triangles: vertices snapped half away from zero") {
    const Image even = render("scenes/catlike-grid.json", false, mesa22);
    const Image away = render("scenes/catlike-grid.json", false, cpu::RasterRules{.triangles_round_half_away = true});
    CHECK(CompareImages(even, away).differing_pixels > 0);
  }
  SECTION("Mesa 25's lines: half-to-even endpoints") {
    const Image away = render("scenes/tinyrenderer-style.json", true, mesa22);
    const Image even = render("scenes/tinyrenderer-style.json", true, cpu::RasterRules{.lines_round_half_even = true});
    CHECK(CompareImages(away, even).differing_pixels > 0);
  }
  SECTION("Mesa 25's wireframes: x and y clipped at the guard band") {
    const Image view = render("scenes/hard/depth-ratio-1e-4.json", true, mesa22);
    const Image guard = render("scenes/hard/depth-ratio-1e-4.json", true, cpu::RasterRules{.wireframe_guard_band = true});
    CHECK(CompareImages(view, guard).differing_pixels > 0);
  }
}
