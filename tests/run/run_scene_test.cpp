// RunScene in process: which backends draw, what is compared and judged, and the verdict each run
// ends with, on the chapter's scene.
#include "run/run_scene.hpp"

#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <cstdlib>

using namespace twinraster;

namespace {

Scene Chapter() { return LoadScene(test::SourcePath("scenes/cgfs-transforms.json")); }

run::RunOptions Options(run::Backends backends, bool verify = false, bool map = false) {
  run::RunOptions options;
  options.backends = backends;
  options.verify = verify;
  options.map = map;
  return options;
}

// Sets an environment variable for one case.
class ScopedEnv {
 public:
  ScopedEnv(const char* name, const char* value) : name_(name) { ::setenv(name, value, 1); }
  ~ScopedEnv() { ::unsetenv(name_); }
  ScopedEnv(const ScopedEnv&) = delete;
  ScopedEnv& operator=(const ScopedEnv&) = delete;

 private:
  const char* name_;
};

}  // namespace

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

TEST_CASE("RunScene: lavapipe and the twin agree bit for bit, GPU first, with nothing to judge", "[run]") {
  const Scene scene = Chapter();
  run::GpuSession gpu({});
  const run::RunResult r = run::RunScene(scene, "chapter", Options(run::Backends::kBoth), gpu);
  REQUIRE(r.record.backends.size() == 2);
  CHECK(r.record.backends[0].backend == run::Backend::kGpu);
  CHECK(r.record.backends[1].backend == run::Backend::kCpu);
  REQUIRE(r.record.comparison);
  CHECK(r.record.comparison->Equal());
  CHECK(r.images[0].rgba == r.images[1].rgba);
  CHECK(r.record.TwinPromised());
  CHECK_FALSE(r.record.verification);
  CHECK(r.record.verdict == run::Verdict::kIdentical);
  CHECK(r.drawn_by[0].device == r.record.backends[0].detail);

  // The session keeps its process: a second scene draws the same pixels.
  const run::RunResult again = run::RunScene(scene, "chapter", Options(run::Backends::kGpu), gpu);
  REQUIRE(again.images.size() == 1);
  CHECK(again.images[0].rgba == r.images[0].rgba);
}

TEST_CASE("RunScene: a crashed GPU process is the verdict, the twin still draws, and the problem names the scene",
          "[run]") {
  const ScopedEnv fault("TWINRASTER_TEST_GPU_FAULT", "abort");
  run::GpuSession gpu({});
  const run::RunResult r = run::RunScene(Chapter(), "scenes/x.json", Options(run::Backends::kBoth, true), gpu);
  REQUIRE(r.record.backends.size() == 2);
  CHECK(r.record.backends[0].status == run::BackendStatus::kCrashed);
  CHECK(r.record.backends[0].problem == "the Vulkan driver crashed (SIGABRT) on scenes/x.json");
  CHECK(r.record.backends[1].Drawn());
  CHECK_FALSE(r.images[1].rgba.empty());
  CHECK_FALSE(r.record.comparison);
  CHECK(r.record.judged == run::Backend::kCpu);  // --verify judges what was drawn
  CHECK(r.record.verdict == run::Verdict::kCrashed);
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
