// The hard scenes against the double-precision ground truth: where depth precision runs out, and
// how far the bit-exact twin (and so lavapipe) may stray from the truth on each, with the reason.
#include "bench/error_metrics.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "truth/truth_renderer.hpp"

#include <map>

using namespace twinraster;

namespace {

struct Rendered {
  Image twin, truth;
};

Rendered RenderBoth(const std::filesystem::path& file) {
  const Scene scene = LoadScene(file);
  const DrawList list = BuildDrawList(scene);
  const truth::ExactLight light(scene);
  return {cpu::RenderOnCpu(list), truth::RenderTruth(list, truth::ExactClipSpace(scene), &light)};
}

// Blue (the far plate) where the truth shows red (the near plate).
std::uint64_t ZFighting(const Rendered& r) {
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < r.twin.rgba.size(); i += 4) {
    count += (r.twin.rgba[i] == 0 && r.twin.rgba[i + 2] == 255 && r.truth.rgba[i] == 255 && r.truth.rgba[i + 2] == 0);
  }
  return count;
}

}  // namespace

TEST_CASE("Depth precision: standard Z fights from near/far = 1e-4, reversed Z never down to 1e-6", "[hard][depth]") {
  for (int exponent = 1; exponent <= 6; ++exponent) {
    for (const bool reversed : {false, true}) {
      const std::string name =
          "scenes/hard/depth-ratio-1e-" + std::to_string(exponent) + (reversed ? "-reversed" : "") + ".json";
      INFO(name);
      const std::uint64_t fighting = ZFighting(RenderBoth(test::SourcePath(name)));
      if (reversed || exponent <= 3) {
        REQUIRE(fighting == 0);
      } else {
        REQUIRE(fighting > 10000);  // most of the visible plate (about 25800 pixels)
      }
    }
  }
}

TEST_CASE("Every hard scene: the twin stays within its documented distance of the truth", "[hard]") {
  // Pixels where the bit-exact twin (= lavapipe) may differ from the double-precision truth, with
  // the reason; measured, and kept tight so that a change in either shows up.
  const std::map<std::string, std::uint64_t> allowed = {
      // Standard Z z-fights (see the depth test above): the far plate shows through.
      {"depth-ratio-1e-4.json", 15004},
      {"depth-ratio-1e-5.json", 18779},
      {"depth-ratio-1e-6.json", 25796},
      // In float the 1e6-scaled cube's near face lands on z = w exactly: depth 1.0 fails LESS
      // against the clear, while in double its depth is 0.99999998667 and it draws.
      {"extreme-scales.json", 11671},
      // A silhouette edge at x = 108.50066 snaps to 108.5 exactly, onto the pixel centres; the
      // top-left rule then takes the whole column that the truth leaves out.
      {"zero-negative-scale.json", 78},
      // Edges passing within 1/512 px of pixel centres: snapping decides them differently.
      {"up-near-parallel.json", 11},
      // Lit: a colour whose exact value is within float rounding of k + 1/2 (of 255) rounds the
      // other way in float; each such pixel is off by 1 (the colour test below holds that).
      {"lit-grazing-light.json", 7},
      {"lit-mirror-scales.json", 6},
  };
  std::size_t judged = 0, listed = 0;
  for (const auto& file : test::ShippedScenes()) {
    if (file.parent_path().filename() != "hard") continue;
    INFO(file.string());
    const Rendered r = RenderBoth(file);
    const std::uint64_t differing = CompareImages(r.twin, r.truth).differing_pixels;
    const auto it = allowed.find(file.filename().string());
    listed += it != allowed.end();
    // Everything else: at most a few pixels whose centres lie within a subpixel of an edge.
    REQUIRE(differing <= (it == allowed.end() ? 4 : it->second));
    ++judged;
  }
  CHECK(judged == 29);              // every scene in scenes/hard
  CHECK(listed == allowed.size());  // and every exception above names one of them
}

TEST_CASE("Lit hard scenes: the twin's colours stay within 1 of the truth's triangle by triangle", "[hard][lighting]") {
  std::size_t lit_scenes = 0;
  for (const auto& file : test::ShippedScenes()) {
    const Scene scene = LoadScene(file);
    if (!scene.lighting) continue;
    ++lit_scenes;
    INFO(file.string());
    const DrawList list = BuildDrawList(scene);
    const truth::ExactLight light(scene);
    const bench::ColourError error =
        bench::SameSurfaceColourError(cpu::RenderOnCpu(list), cpu::RenderOnCpu(*bench::SurfaceList(list)),
                                      truth::RenderTruthSurfaces(list, truth::ExactClipSpace(scene), &light));
    CHECK(error.pixels > 5000);  // the comparison covers most of each picture
    CHECK(error.max_channel <= 1);
  }
  REQUIRE(lit_scenes == 9);  // of the 46 shipped scenes
}
