// The four ways of computing clip-space positions: the default one is exactly what the renderers
// compute, all agree on ordinary scenes, and far from the origin only the double-composed ones hold.
#include "bench/vertex_methods.hpp"

#include "bench/error_metrics.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "truth/truth_renderer.hpp"

using namespace twinraster;

namespace {
Scene Load(const std::string& relative) { return LoadScene(test::SourcePath(relative)); }
}  // namespace

TEST_CASE("compose-f64 through RasterizeClipSpace makes exactly the renderers' image", "[methods]") {
  std::size_t judged = 0;
  for (const auto& file : test::ShippedScenes()) {
    INFO(file.string());
    const Scene scene = LoadScene(file);
    const DrawList list = BuildDrawList(scene);
    if (list.width * list.height > 400'000) continue;  // the smaller scenes are enough here
    const Image direct = cpu::RenderOnCpu(list);
    const Image via_clip =
        cpu::RasterizeClipSpace(list, bench::TransformVertices(scene, list, bench::VertexMethod::kComposeDouble));
    REQUIRE(direct.rgba == via_clip.rgba);
    ++judged;
  }
  CHECK(judged == 38);  // of the 46, those up to 400 000 pixels
}

TEST_CASE("On the chapter's scenes every method lands within 1e-3 px of the truth", "[methods]") {
  for (const char* name : {"scenes/cgfs-transforms.json", "scenes/lookat.json", "scenes/catlike-rotations.json"}) {
    INFO(name);
    const Scene scene = Load(name);
    const DrawList list = BuildDrawList(scene);
    const truth::ExactClipPositions exact = truth::ExactClipSpace(scene);
    for (bench::VertexMethod method : bench::kAllMethods) {
      INFO(bench::MethodName(method));
      const double error =
          bench::VertexErrorPixels(bench::TransformVertices(scene, list, method), exact, list.width, list.height);
      REQUIRE(error > 0);  // float is never exact here: the measurement is live
      REQUIRE(error < 1e-3);
    }
  }
}

TEST_CASE("1e7 units from the origin: composing in double keeps vertices within 1/256 px, float does not",
          "[methods][hard]") {
  const Scene scene = Load("scenes/hard/far-1e7.json");
  const DrawList list = BuildDrawList(scene);
  const truth::ExactClipPositions exact = truth::ExactClipSpace(scene);
  const auto error = [&](bench::VertexMethod m) {
    return bench::VertexErrorPixels(bench::TransformVertices(scene, list, m), exact, list.width, list.height);
  };
  REQUIRE(error(bench::VertexMethod::kCameraRelative) < 1.0 / 256);
  REQUIRE(error(bench::VertexMethod::kComposeDouble) < 1.0 / 256);
  // Float has a spacing of 1 unit at 1e7: the scene, a few units across, falls apart.
  REQUIRE(error(bench::VertexMethod::kComposeFloat) > 10);
  REQUIRE(error(bench::VertexMethod::kStepsFloat) > 10);
}

TEST_CASE("Vertex error grows with the distance from the origin for float composition only", "[methods][hard]") {
  double previous = 0;
  for (const char* name : {"scenes/hard/far-1e3.json", "scenes/hard/far-1e5.json", "scenes/hard/far-1e7.json"}) {
    INFO(name);
    const Scene scene = Load(name);
    const DrawList list = BuildDrawList(scene);
    const truth::ExactClipPositions exact = truth::ExactClipSpace(scene);
    const double f32 = bench::VertexErrorPixels(
        bench::TransformVertices(scene, list, bench::VertexMethod::kComposeFloat), exact, list.width, list.height);
    const double relative = bench::VertexErrorPixels(
        bench::TransformVertices(scene, list, bench::VertexMethod::kCameraRelative), exact, list.width, list.height);
    REQUIRE(f32 > previous);
    REQUIRE(relative < 1.0 / 256);
    previous = f32;
  }
}

TEST_CASE("RasterizeClipSpace refuses positions that do not match the draw list", "[methods]") {
  const Scene scene = Load("scenes/cgfs-scene.json");
  const DrawList list = BuildDrawList(scene);
  cpu::ClipPositions clip = bench::TransformVertices(scene, list, bench::VertexMethod::kComposeDouble);
  clip[0].pop_back();
  REQUIRE_THROWS_AS(cpu::RasterizeClipSpace(list, clip), std::invalid_argument);
  REQUIRE_THROWS_AS(cpu::RasterizeClipSpace(list, {}), std::invalid_argument);
}
