// Every shipped scene renders identically on lavapipe and on the CPU twin: 0 differing pixels.
#include "chain/draw_list.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <catch2/catch.hpp>

using namespace twinraster;

TEST_CASE("Every shipped scene: GPU image == CPU image, bit for bit", "[twin]") {
  for (const auto& file : test::ShippedScenes()) {
    INFO(file.string());
    const Scene scene = LoadScene(file);
    const test::TwinResult r = test::RenderTwins(BuildDrawList(scene));
    INFO(r.Describe());
    REQUIRE(r.Equal());
    // Not a blank image: the scene drew something besides the background.
    std::size_t drawn = 0;
    for (std::uint32_t y = 0; y < r.cpu.height; ++y)
      for (std::uint32_t x = 0; x < r.cpu.width; ++x) {
        const std::uint8_t* p = r.cpu.pixel(x, y);
        const Rgb8 bg = scene.canvas.background;
        drawn += (p[0] != bg.r || p[1] != bg.g || p[2] != bg.b) ? 1 : 0;
      }
    REQUIRE(drawn > 100);
  }
  test::RequireNoValidationMessages();
}
