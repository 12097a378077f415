#include "bench/verify_bench.hpp"

#include "bench/bench_suite.hpp"
#include "bench/process_bench.hpp"
#include "files/png_file.hpp"
#include "image/image_compare.hpp"
#include "run/run_scene.hpp"
#include "scene/obj_scene.hpp"

#include <algorithm>

namespace twinraster::bench {

namespace {

// `render` and `verify` of one scene as a user runs them, in turn, so that the machine's drift
// falls on each alike. The failing image keeps the passing one's notes, so that both are judged
// by the same device's rules.
VerifyProcessRow TimeProcesses(const std::filesystem::path& executable, const std::filesystem::path& scene, int runs) {
  const TemporaryDirectory work;
  const std::string exe = executable.string(), file = scene.string();
  const std::string drawn = (work.path() / "twin.png").string(), shifted = (work.path() / "shifted.png").string();
  const std::string out = (work.path() / "out.png").string();
  TimedProcess({exe, "render", "-q", file, "--backend", "cpu", "-o", drawn});
  files::WritePng(shifted, ShiftedRight(files::ReadPng(drawn)), files::kPngFastest, files::ReadPngNotes(drawn));
  constexpr int kViolations = 1;  // verify's exit code for an image with violations
  std::vector<double> render, passing, failing;
  for (int i = 0; i < runs; ++i) {
    render.push_back(TimedProcess({exe, "render", "-q", file, "--backend", "cpu", "-o", out}));
    passing.push_back(TimedProcess({exe, "verify", file, drawn}));
    failing.push_back(TimedProcess({exe, "verify", file, shifted}, kViolations));
  }
  return {.scene = file,
          .render_ms = Median(render),
          .verify_passing_ms = Median(passing),
          .verify_failing_ms = Median(failing)};
}

}  // namespace

std::vector<std::filesystem::path> DefaultVerifyBenchScenes(const std::filesystem::path& scenes_dir) {
  return {scenes_dir / "cgfs-transforms.json", scenes_dir / "lit-gouraud.json", scenes_dir / "one-million-cubes.json"};
}

VerifyBenchResult RunVerifyBench(const std::vector<std::filesystem::path>& scenes, int runs,
                                 const std::filesystem::path& executable) {
  VerifyBenchResult result;
  result.runs = runs;
  result.machine = MachineDescription("not used");
  // The twin drawing and the verifier judging its image, as `render --backend cpu --verify` runs
  // them: side by side in each run, so that the machine's load falls on both alike.
  run::RunOptions options;
  options.backends = run::Backends::kCpu;
  options.verify = true;
  run::GpuSession no_gpu({});  // --backend cpu: never started
  for (const auto& file : scenes) {
    const Scene scene = LoadSceneOrObj(file);
    VerifyBenchRow row;
    row.scene = file.string();
    std::vector<double> twin, verify;
    for (int i = 0; i < runs; ++i) {
      const run::RunRecord r = run::RunScene(scene, row.scene, options, no_gpu).record;
      const run::BackendRecord& drawn = r.backends.front();
      twin.push_back(drawn.setup_ms + drawn.draw_ms + drawn.readback_ms);
      verify.push_back(r.verify_ms);
      row.width = r.width, row.height = r.height, row.triangles = r.triangles;
      row.twin_threads = drawn.threads;
      row.uncertain = r.verification->uncertain, row.covered = r.verification->covered;
      row.violations = r.verification->violations;
    }
    row.twin_ms = Median(twin), row.verify_ms = Median(verify);
    result.rows.push_back(row);
  }
  if (!executable.empty()) {
    for (const auto& file : scenes) result.processes.push_back(TimeProcesses(executable, file, runs));
  }
  return result;
}

}  // namespace twinraster::bench
