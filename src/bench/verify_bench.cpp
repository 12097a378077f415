#include "bench/verify_bench.hpp"

#include "bench/bench_suite.hpp"
#include "run/run_scene.hpp"
#include "scene/obj_scene.hpp"

#include <algorithm>

namespace twinraster {

std::vector<std::filesystem::path> DefaultVerifyBenchScenes(const std::filesystem::path& scenes_dir) {
  return {scenes_dir / "cgfs-transforms.json", scenes_dir / "lit-gouraud.json", scenes_dir / "one-million-cubes.json"};
}

VerifyBenchResult RunVerifyBench(const std::vector<std::filesystem::path>& scenes, int runs) {
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
  return result;
}

}  // namespace twinraster
