// RunScene in process on lavapipe (built only with Vulkan): the GPU and the twin agreeing bit for bit
// in one session, and a crashed GPU process as the verdict. What draws on the twin alone is in
// run_scene_test.cpp.
#include "chapter_run.hpp"
#include "run/run_scene.hpp"
#include "support/catch.hpp"

#include <cstdlib>

using namespace twinraster;
using test::Chapter;
using test::Options;

namespace {

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
