// How `render` goes through its scenes, as a batch: which failures are a scene's own (said,
// recorded with verdict error, and the batch goes on) and which end the run; when one scene's own
// failure is recorded rather than the run's (exit 2); with several scenes, the writer thread that
// writes and prints each scene, in order, while the next draws; and the tally of every record into
// one run::BatchResult. It neither names files (render_files.hpp) nor formats what it prints
// (render_printing.hpp).
#pragma once

#include "base/serial_queue.hpp"
#include "cli/progress.hpp"
#include "cli/render_arguments.hpp"
#include "run/batch_result.hpp"
#include "run/run_scene.hpp"

#include <functional>
#include <string>

namespace twinraster::cli {

class RenderBatch {
 public:
  RenderBatch(const RenderArguments& a, Progress& progress);

  // What the GPU process calls before it forks: with several scenes, a wait for the writer to be
  // idle (IsolationOptions::before_fork); nothing for one.
  std::function<void()> BeforeFork();
  // Reads and draws `scene`, then writes, prints and tallies it: at once for one scene, on the
  // writer thread for several. Throws what is not the scene's own failure (GpuUnavailable, ...).
  void Render(const std::string& scene, run::GpuSession& gpu);
  // Waits for every scene to be written (rethrowing the writer's error) and returns the batch.
  run::BatchResult Finish();

 private:
  void InTurn(const std::string& scene, run::GpuSession& gpu);
  void Queued(const std::string& scene, run::GpuSession& gpu);
  void Failed(const std::string& scene, const std::string& message);
  const run::RunRecord& Tally(run::RunRecord record);

  const RenderArguments& a_;
  Progress& progress_;
  const bool several_;
  // One scene's own failure is recorded, not the run's, when a batch, a report, a JUnit file or
  // JSON is asked for: each has a place to say it.
  const bool keep_going_;
  run::BatchResult batch_;
  // Declared last, so destroyed first: tasks still queued when the run fails run with batch_ alive.
  SerialQueue writer_{2};  // each waiting task holds a scene's images
};

}  // namespace twinraster::cli
