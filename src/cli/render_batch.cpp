#include "cli/render_batch.hpp"

#include "cli/render_printing.hpp"
#include "cli/render_scene.hpp"
#include "files/staged_file.hpp"
#include "scene/scene_error.hpp"

#include <exception>
#include <memory>
#include <utility>

namespace twinraster::cli {

namespace {

// Whether a scene's failure is its own (bad input, an output that cannot be written), which a batch
// reports and goes on from, rather than the run's.
bool SceneOwnError(const std::exception& e) {
  return dynamic_cast<const SceneError*>(&e) || dynamic_cast<const files::FileError*>(&e);
}

}  // namespace

RenderBatch::RenderBatch(const RenderArguments& a, Progress& progress)
    : a_(a),
      progress_(progress),
      several_(a.scenes.size() > 1),
      keep_going_(several_ || a.report || a.junit || a.json) {}

std::function<void()> RenderBatch::BeforeFork() {
  if (!several_) return {};
  return [this] { writer_.WaitIdle(); };
}

void RenderBatch::Render(const std::string& scene, run::GpuSession& gpu) {
  if (several_) {
    Queued(scene, gpu);
  } else {
    InTurn(scene, gpu);
  }
}

run::BatchResult RenderBatch::Finish() {
  if (several_) writer_.Finish();
  return std::move(batch_);
}

// One scene: read, draw, write, print, here and now.
void RenderBatch::InTurn(const std::string& scene, run::GpuSession& gpu) {
  try {
    DrawnScene drawn = DrawScene(a_, scene, gpu, progress_);
    PrintRecord(a_, Tally(WriteScene(a_, drawn, progress_)), false);
  } catch (const std::exception& e) {
    if (!SceneOwnError(e) || !keep_going_) throw;
    Failed(scene, e.what());
  }
}

// Several scenes, each on its own: a bad scene or an unwritable output is reported and the others
// still render. Each scene's files are written and its record printed on the writer thread, in
// order, while the next scene draws: the PNGs and the file system's waits take the other core.
void RenderBatch::Queued(const std::string& scene, run::GpuSession& gpu) {
  try {
    auto drawn = std::make_shared<DrawnScene>(DrawScene(a_, scene, gpu, progress_));
    writer_.Push([this, scene, drawn] {
      try {
        const run::RunRecord& record = Tally(WriteScene(a_, *drawn, progress_));
        progress_.Above([&] { PrintRecord(a_, record, true); });
      } catch (const std::exception& e) {
        if (!SceneOwnError(e)) throw;
        Failed(scene, e.what());
      }
    });
  } catch (const std::exception& e) {
    if (!SceneOwnError(e)) throw;  // the queue's scenes are still written first
    writer_.Push([this, scene, what = std::string(e.what())] { Failed(scene, what); });
  }
}

// A scene that failed on its own: a record of verdict error, which the batch keeps and --json
// prints as any other scene's.
void RenderBatch::Failed(const std::string& scene, const std::string& message) {
  run::RunRecord failed = run::ErrorRecord(scene, message);
  failed.rules = a_.run.rules;
  const run::RunRecord& record = Tally(std::move(failed));
  progress_.Above([&] { PrintFailure(a_, message, record, several_); });
}

// Every output reads the batch's copy of the record: the JSON line now, the page and JUnit later.
const run::RunRecord& RenderBatch::Tally(run::RunRecord record) {
  batch_.Add(std::move(record));
  return batch_.Records().back();
}

}  // namespace twinraster::cli
