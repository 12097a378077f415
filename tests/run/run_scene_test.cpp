// RunScene in process with the twin alone, in a build with or without Vulkan: what it draws, what is
// judged, and the verdict each run ends with, on the chapter's scene. What draws on lavapipe is in
// run_scene_device_test.cpp.
#include "run/run_scene.hpp"

#include "chapter_run.hpp"
#include "support/catch.hpp"

using namespace twinraster;
using test::Chapter;
using test::Options;

TEST_CASE("RunScene: the twin alone draws the canvas, copies the default lavapipe, and is only rendered", "[run]") {
  const Scene scene = Chapter();
  run::GpuSession gpu({});
  const run::RunResult r = run::RunScene(scene, "chapter", Options(run::Backends::kCpu), gpu);
  REQUIRE(r.record.backends.size() == 1);
  REQUIRE(r.images.size() == 1);
  CHECK(r.record.backends[0].backend == run::Backend::kCpu);
  CHECK(r.record.backends[0].Drawn());
  CHECK(r.record.backends[0].threads > 0);
  CHECK(r.images[0].width == scene.canvas.width);
  CHECK(r.images[0].height == scene.canvas.height);
  CHECK(r.drawn_by[0].device == "CPU twin");
  CHECK(r.drawn_by[0].rasterizes.subpixel_bits == 8);
  REQUIRE(r.record.twin);
  CHECK_FALSE(r.record.comparison);
  CHECK_FALSE(r.record.verification);
  CHECK_FALSE(r.diff);
  CHECK(r.record.triangles == 24);
  CHECK(r.record.verdict == run::Verdict::kRendered);
}

TEST_CASE("RunScene: asked to verify, the twin's image is judged, passes, and its map is kept when asked", "[run]") {
  const Scene scene = Chapter();
  run::GpuSession gpu({});
  const run::RunResult without_map = run::RunScene(scene, "chapter", Options(run::Backends::kCpu, true), gpu);
  REQUIRE(without_map.record.verification);
  CHECK(without_map.record.judged == run::Backend::kCpu);
  CHECK(without_map.record.verification->pixels.empty());  // the record stays small
  CHECK_FALSE(without_map.map);
  CHECK(without_map.record.verdict == run::Verdict::kVerified);

  const run::RunResult with_map = run::RunScene(scene, "chapter", Options(run::Backends::kCpu, true, true), gpu);
  REQUIRE(with_map.map);
  CHECK(with_map.map->width == scene.canvas.width);
  CHECK(with_map.record.verdict == run::Verdict::kVerified);
}

TEST_CASE("RunScene: by the book's rules, one CPU wireframe that is never judged", "[run]") {
  run::RunOptions options = Options(run::Backends::kCpu, true);
  options.rules = run::Rules::kBook;
  run::GpuSession gpu({});
  const run::RunResult r = run::RunScene(Chapter(), "chapter", options, gpu);
  REQUIRE(r.record.backends.size() == 1);
  CHECK(r.record.backends[0].detail == "book rules: the chapter's demos, 1 thread");
  CHECK(r.record.wireframe);
  CHECK_FALSE(r.record.twin);
  CHECK_FALSE(r.record.verification);
  CHECK(r.record.verdict == run::Verdict::kRendered);
}
