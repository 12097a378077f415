// Where every file `render` writes goes, and how each is staged: a scene's images, their maps,
// the diff and the page's thumbnails (all renamed into place together, or none), and the batch's
// page and JUnit file. It draws, judges and prints nothing; report/ makes the bytes of the page.
#pragma once

#include "cli/render_arguments.hpp"
#include "files/staged_file.hpp"
#include "run/batch_result.hpp"
#include "run/run_scene.hpp"

#include <string>
#include <vector>

namespace twinraster::cli {

// A scene's PNG (or the stem of its PNGs): in the directory, -o OUT.png, - or the scene's name.
std::string SceneOut(const RenderArguments& a, const std::string& scene_argument);

// Every destination checked (docs/commands.md, "Output paths") and its missing directories made,
// before any scene is read or the GPU process started; throws FileError.
void PrepareDestinations(const RenderArguments& a);

// Names and encodes every image of the run, each staged in full before any is renamed into place
// (or, for -o -, kept in `png_bytes` for standard output), and records the files in the run's
// record.
std::vector<files::StagedFile> StageImages(run::RunResult& result, const RenderArguments& a, const std::string& out,
                                           std::string& png_bytes);

// Removes a diff an earlier run left at `out`'s name when this run compared and wrote none: it
// would describe images that no longer exist.
void RemoveStaleDiff(const run::RunResult& result, const std::string& out);

// The page and the JUnit file, staged together after the batch: all of them or neither.
void WriteBatchReports(const RenderArguments& a, const run::BatchResult& batch);

}  // namespace twinraster::cli
