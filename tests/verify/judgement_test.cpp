// The judgement of a whole image: passed, failed or inconclusive; an empty image never passes; lines judged
// by strictLines where the device reports it; a line clipped at the canvas's border or beyond it; a
// scene whose overdraw is over the work budget found inconclusive before any pixel is judged.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "run/verdict.hpp"
#include "run_report/coverage_report.hpp"
#include "run_report/verify_report.hpp"
#include "scene/gltf_document.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/gltf_bytes.hpp"
#include "support/test_support.hpp"
#include "verify/coverage_judgement.hpp"
#include "verify/verifier.hpp"
#include "verify/work_estimate.hpp"
#include "verify_scenes.hpp"

using namespace twinraster;

namespace {

Image Blank(const DrawList& list) {
  Image image(list.width, list.height);
  for (std::uint32_t y = 0; y < list.height; ++y) {
    for (std::uint32_t x = 0; x < list.width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      p[0] = list.background.r, p[1] = list.background.g, p[2] = list.background.b, p[3] = 255;
    }
  }
  return image;
}

// One triangle, one of whose corners is `z` units in front of the eye (behind it when negative).
std::string TriangleScene(double z) {
  return R"({"canvas": {"width": 64, "height": 48, "background": [255, 255, 255]},
    "viewport": {"width": 1.3333333333333333, "height": 1, "distance": 1}, "depth": {"near": 0.5, "far": 50},
    "camera": {"position": [0, 0, 0]},
    "models": {"t": {"vertices": [[0, -1, )" +
         std::to_string(z) + R"(], [-1, 0.5, 3], [1, 0.5, 3]], "triangles": [[0, 1, 2, "red"]]}},
    "instances": [{"model": "t"}], "wireframe": true})";
}

}  // namespace

TEST_CASE("verify: an empty image of a scene that draws something never passes, filled or in wireframe", "[verify]") {
  int judged = 0, failed = 0;
  for (const auto& file : test::ShippedScenes()) {
    for (const bool wireframe : {false, true}) {
      const auto [scene, list] = test::ShippedScene(file, wireframe);
      for (const verify::VerifyOptions options : {verify::VerifyOptions{4, false}, verify::VerifyOptions{8, true}}) {
        const verify::Verification v = verify::VerifyImage(scene, list, Blank(list), options);
        INFO(file.string() << (wireframe ? " --wireframe" : "") << ": " << run_report::VerificationText(v));
        CHECK(verify::JudgementOf(v) != verify::Judgement::kPassed);
        failed += verify::JudgementOf(v) == verify::Judgement::kFailed;
        ++judged;
      }
    }
  }
  CHECK(judged == int(test::ShippedScenes().size()) * 4);
  CHECK(failed >= judged * 9 / 10);  // mostly caught outright; the rest cannot tell
}

TEST_CASE("verify: an empty image of a random scene that draws something never passes", "[verify][random]") {
  int drawing = 0;
  for (std::uint32_t seed = 1; seed <= 100; ++seed) {
    for (const bool wireframe : {false, true}) {
      const auto [scene, list] = test::RandomScene(seed, wireframe);
      const Image empty = Blank(list);
      if (cpu::RenderOnCpu(list).rgba == empty.rgba) continue;  // draws nothing: an empty image is right
      const verify::Verification v = verify::VerifyImage(scene, list, empty, {8, true});
      INFO("seed " << seed << (wireframe ? " --wireframe: " : ": ") << run_report::VerificationText(v));
      CHECK(verify::JudgementOf(v) != verify::Judgement::kPassed);
      ++drawing;
    }
  }
  CHECK(drawing >= 160);  // the random scenes mostly draw something (twin/random_scenes_test asks 80 %)
}

TEST_CASE("verify: where every pixel is uncertain the judgement is inconclusive, not passed", "[verify]") {
  // Vertices 1e8 units across through the eye: no edge's place is known to a pixel.
  const Scene scene = ParseScene(R"({"canvas": {"width": 32, "height": 32, "background": [0, 0, 0]},
    "viewport": {"width": 1, "height": 1, "distance": 1}, "depth": {"near": 1e-6, "far": 1e9},
    "camera": {"position": [0, 0, 0]},
    "models": {"t": {"vertices": [[-1e8, -1e8, 1e-5], [1e8, -1e8, 1e-5], [0, 1e8, 1e8]], "triangles": [[0, 1, 2, "red"]]}},
    "instances": [{"model": "t"}]})",
                                 "huge.json");
  const DrawList list = BuildDrawList(scene);
  const verify::Verification drawn = verify::VerifyImage(scene, list, cpu::RenderOnCpu(list), {8, true});
  const verify::Verification empty = verify::VerifyImage(scene, list, Blank(list), {8, true});
  INFO(run_report::VerificationText(drawn) << "\n" << run_report::VerificationText(empty));
  CHECK(drawn.NoViolations());
  CHECK(verify::JudgementOf(drawn) == verify::Judgement::kInconclusive);
  CHECK(verify::JudgementOf(empty) != verify::Judgement::kPassed);
}

TEST_CASE("verify: strict lines are sharper than non-strict ones, and the twin's lines pass both", "[verify]") {
  int sharper = 0, judged = 0;
  for (const auto& file : test::ShippedScenes()) {
    const auto [scene, list] = test::ShippedScene(file, true);
    const Image image = cpu::RenderOnCpu(list);
    const verify::Verification loose = verify::VerifyImage(scene, list, image, {8, false});
    const verify::Verification strict = verify::VerifyImage(scene, list, image, {8, true});
    INFO(file.string() << ": " << run_report::VerificationText(loose) << "\n" << run_report::VerificationText(strict));
    CHECK(loose.NoViolations());
    CHECK(strict.NoViolations());
    CHECK(strict.UncertainOther() <= loose.UncertainOther());
    sharper += strict.UncertainOther() < loose.UncertainOther();
    ++judged;
  }
  CHECK(judged == int(test::ShippedScenes().size()));
  CHECK(sharper >= judged / 2);
}

TEST_CASE("verify: an edge through the eye plane must be drawn where it is in front of the near plane", "[verify]") {
  // The twin draws the clipped polygon's edges; an image without the two edges that run to the
  // corner behind the eye breaks Polygon Mode's "the polygon is clipped ... before these modes are
  // applied" (docs/verify.md: SwiftShader does this).
  const Scene scene = ParseScene(TriangleScene(-1), "behind.json");
  const DrawList list = BuildDrawList(scene);
  const Image drawn = cpu::RenderOnCpu(list);
  Image dropped = Blank(list);
  for (std::uint32_t x = 0; x < list.width; ++x) {  // keep the one edge in front: row 15, as drawn
    std::copy_n(drawn.pixel(x, 15), 4, dropped.pixel(x, 15));
  }
  const verify::Verification good = verify::VerifyImage(scene, list, drawn, {8, true});
  const verify::Verification bad = verify::VerifyImage(scene, list, dropped, {8, true});
  INFO(run_report::VerificationText(good) << "\n" << run_report::VerificationText(bad));
  CHECK(good.NoViolations());
  CHECK(verify::JudgementOf(bad) == verify::Judgement::kFailed);
  CHECK(bad.violations >= 20);
}

TEST_CASE("verify: a line that grazes the canvas's edge may start anywhere beyond it", "[verify]") {
  // Nearly horizontal, crossing the top border far from either endpoint: an implementation that
  // clips at the viewport ends it at the border, one with a guard band (Mesa 25) or none draws on.
  const Scene scene = ParseScene(R"({"canvas": {"width": 512, "height": 8, "background": [255, 255, 255]},
    "viewport": {"width": 64, "height": 1, "distance": 1, "projection": "orthographic"},
    "camera": {"position": [0, 0, 0]},
    "models": {"t": {"vertices": [[-40, 0.52, 2], [200, 0.44, 2], [-40, -0.4, 2]], "triangles": [[0, 1, 2, "blue"]]}},
    "instances": [{"model": "t"}], "wireframe": true})",
                                 "graze.json");
  const DrawList list = BuildDrawList(scene);
  const Image twin = cpu::RenderOnCpu(list);
  cpu::CpuOptions guard;
  guard.rules.wireframe_guard_band = true;
  const Image guarded = cpu::RenderOnCpu(list, guard);
  for (const Image* image : {&twin, &guarded}) {
    const verify::Verification v = verify::VerifyImage(scene, list, *image, {8, true});
    INFO(run_report::VerificationText(v));
    CHECK(v.NoViolations());
  }
}

namespace {

// A glTF file of `primitives` primitives that all read one accessor: a triangle over most of the
// canvas, so the verifier's work grows as primitives x canvas while the file grows by 30 bytes a
// primitive (an overdraw attack's shape).
std::string StackedTriangles(int primitives) {
  std::vector<std::uint8_t> bytes;
  for (const float f : {-1.f, -1.f, 0.f, 1.f, -1.f, 0.f, 0.f, 1.f, 0.f}) test::AppendBytes(bytes, f);
  std::string text = R"({"asset": {"version": "2.0"}, "nodes": [{"mesh": 0}],
    "buffers": [{"byteLength": 36, "uri": "data:application/octet-stream;base64,)" +
                     test::Base64(bytes) + R"("}], "bufferViews": [{"buffer": 0, "byteLength": 36}],
    "accessors": [{"bufferView": 0, "componentType": 5126, "count": 3, "type": "VEC3"}],
    "meshes": [{"primitives": [)";
  for (int i = 0; i < primitives; ++i) text += std::string(i ? "," : "") + R"({"attributes": {"POSITION": 0}})";
  return text + "]}]}";
}

}  // namespace

TEST_CASE("verify: a scene whose overdraw is over the work budget is inconclusive, saying so, not judged for hours",
          "[verify]") {
  const std::string text = StackedTriangles(40);
  SceneChoice small;
  small.size = CanvasSize{64, 48};
  const Scene scene =
      GltfScene(ParseGltf(std::vector<std::uint8_t>(text.begin(), text.end()), "stack.gltf", {}), small, "stack");
  const DrawList list = BuildDrawList(scene);
  const Image twin = cpu::RenderOnCpu(list);
  // The estimate: 40 equal boxes, each within the canvas, the framed triangle's (an eighth or more).
  const std::uint64_t estimate = verify::EstimatePixelTests(list, std::uint64_t(-1));
  CHECK(estimate % 40 == 0);
  CHECK(estimate / 40 <= 64u * 48);
  CHECK(estimate / 40 >= 64u * 48 / 8);
  CHECK(verify::EstimatePixelTests(list, 1000) <= 1000 + estimate / 40);  // stops counting past the bound
  const verify::Verification judged = verify::VerifyImage(scene, list, twin, {8, true});
  INFO(run_report::VerificationText(judged));
  CHECK(verify::JudgementOf(judged) == verify::Judgement::kPassed);  // the default budget is far above
  CHECK(judged.work.pixel_tests == estimate);
  verify::VerifyOptions tight{8, true};
  tight.pixel_test_budget = estimate - 1;
  const verify::Verification over = verify::VerifyImage(scene, list, twin, tight);
  CHECK(verify::JudgementOf(over) == verify::Judgement::kInconclusive);
  CHECK(run::ExitCodeOf(run::VerdictOf(verify::JudgementOf(over))) == run::ExitCodeOf(run::Verdict::kInconclusive));
  CHECK(run_report::InconclusiveReason(over) == "too much overdraw to judge within the budget: at least " +
                                                    std::to_string(estimate) + " pixel tests, budget " +
                                                    std::to_string(estimate - 1));
  CHECK(run_report::VerificationText(over).rfind("inconclusive: too much overdraw", 0) == 0);
  // An image that is plainly wrong is not judged either: nothing was, so nothing can fail.
  CHECK(verify::JudgementOf(verify::VerifyImage(scene, list, Blank(list), tight)) == verify::Judgement::kInconclusive);
  // --coverage reads the same verification, and says the same.
  tight.reach = true;
  const verify::CoverageVerification coverage =
      verify::JudgeCoverage(verify::VerifyImage(scene, list, twin, tight), twin, list.background, {});
  CHECK(verify::JudgementOf(coverage) == verify::Judgement::kInconclusive);
  CHECK_THAT(run_report::CoverageText(coverage), HasSubstring("too much overdraw to judge within the budget"));
}
