// One scene of `render`, in two steps: read and drawn (run/run_scene.hpp runs it), then its files
// written. Everything is drawn before anything is written, so that a run that fails writes no file
// at all. It decides nothing about the batch (render_batch.hpp does) and prints no record.
#pragma once

#include "base/stopwatch.hpp"
#include "cli/progress.hpp"
#include "cli/render_arguments.hpp"
#include "run/run_record.hpp"
#include "run/run_scene.hpp"

#include <string>

namespace twinraster::cli {

// A scene read and drawn, its files not yet written.
struct DrawnScene {
  run::RunResult result;
  std::string out;  // its PNG (or the stem of its PNGs), or - for standard output
  Stopwatch clock;  // since the scene began to be read
};

// Reads one scene and runs it; throws SceneError for the scene's own problems (the book's rules'
// among them), as the loader does.
DrawnScene DrawScene(const RenderArguments& a, const std::string& scene_argument, run::GpuSession& gpu,
                     Progress& progress);

// Writes a drawn scene's files (PNG bytes for -o - to standard output) and returns its record, with
// the files named and its total time; throws FileError.
run::RunRecord WriteScene(const RenderArguments& a, DrawnScene& drawn, Progress& progress);

}  // namespace twinraster::cli
