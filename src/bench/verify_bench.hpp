// `twinraster bench --verify`: what judging a frame costs against drawing it, per scene: the CPU
// twin's render and the verifier's judgement of that image, side by side, medians; then the same as
// whole processes, `render` against `verify` of an image that passes and of one that fails. It does
// not judge any device's image but the twin's.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace twinraster::bench {

struct VerifyBenchRow {
  std::string scene;
  std::uint32_t width = 0, height = 0;
  std::size_t triangles = 0;
  unsigned twin_threads = 0;
  double twin_ms = 0;    // RenderOnCpu: vertex stage to image, median
  double verify_ms = 0;  // VerifyImage of that image at lavapipe's 8 subpixel bits, median
  double Ratio() const { return twin_ms > 0 ? verify_ms / twin_ms : 0.0; }
  std::uint64_t uncertain = 0, covered = 0, violations = 0;
};

// One scene as whole processes, medians of runs in turn, milliseconds: `render -q SCENE --backend cpu
// -o OUT.png`, and `verify SCENE IMAGE.png` (its map written beside, as by default) of the twin's
// image, which passes, and of that image shifted one pixel right, which fails.
struct VerifyProcessRow {
  std::string scene;
  double render_ms = 0, verify_passing_ms = 0, verify_failing_ms = 0;
  double PassingRatio() const { return render_ms > 0 ? verify_passing_ms / render_ms : 0.0; }
  double FailingRatio() const { return render_ms > 0 ? verify_failing_ms / render_ms : 0.0; }
};

struct VerifyBenchResult {
  std::vector<VerifyBenchRow> rows;
  std::vector<VerifyProcessRow> processes;  // empty when not measured
  std::string machine;
  int runs = 0;
};

// The chapter's scene, lit-gouraud and the million cubes at 1920 x 1080 by default.
std::vector<std::filesystem::path> DefaultVerifyBenchScenes(const std::filesystem::path& scenes_dir);
// `executable` (twinraster itself) times the whole processes too; empty, it does not.
VerifyBenchResult RunVerifyBench(const std::vector<std::filesystem::path>& scenes, int runs,
                                 const std::filesystem::path& executable = {});

}  // namespace twinraster::bench
