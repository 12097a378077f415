#include "cli/render_scene.hpp"

#include "book/book_renderer.hpp"
#include "cli/io_arguments.hpp"
#include "cli/render_files.hpp"
#include "cli/scene_choice_options.hpp"
#include "scene/scene_error.hpp"

#include <utility>

namespace twinraster::cli {

namespace {

// A report shows the map of every judgement; --verify asks for it; -o - has nowhere to put it.
run::RunOptions RunOptionsOf(const RenderArguments& a, bool to_stdout) {
  run::RunOptions options = a.run;
  options.map = (a.verify || a.report) && !to_stdout;
  return options;
}

}  // namespace

DrawnScene DrawScene(const RenderArguments& a, const std::string& scene_argument, run::GpuSession& gpu,
                     Progress& progress) {
  progress.Status("reading " + scene_argument + "...");
  DrawnScene drawn;
  const std::string source = IsStandardStream(scene_argument) ? "<stdin>" : scene_argument;
  Scene scene = LoadSceneArgument(scene_argument, ChoiceOf(a.choice));
  if (!a.quiet) PrintSceneNotes(scene, source);
  const double load_ms = drawn.clock.Milliseconds();
  if (a.wireframe) scene.wireframe = true;
  drawn.out = SceneOut(a, scene_argument);
  try {
    drawn.result = run::RunScene(scene, source, RunOptionsOf(a, IsStandardStream(drawn.out)), gpu,
                                 [&](std::string_view text) { progress.Status(text); });
  } catch (const book::BookRulesError& e) {
    // A problem with the scene, like the loader's, so that several scenes go on.
    throw SceneError(source, e.where(), "--rules book: " + e.problem());
  }
  drawn.result.record.scene = scene_argument;
  drawn.result.record.load_ms = load_ms;
  return drawn;
}

// Writes a drawn scene's files and returns its record (which render prints, and the page and JUnit
// file read).
run::RunRecord WriteScene(const RenderArguments& a, DrawnScene& drawn, Progress& progress) {
  run::RunResult& result = drawn.result;
  progress.Status(result.record.backends.size() == 1 ? "writing the PNG..." : "writing the PNGs...");
  std::string png_bytes;  // for -o -
  for (files::StagedFile& file : StageImages(result, a, drawn.out, png_bytes)) file.Commit();
  RemoveStaleDiff(result, drawn.out);
  progress.Clear();
  if (!png_bytes.empty()) WriteStandardOutput(png_bytes);
  result.record.total_ms = drawn.clock.Milliseconds();
  return std::move(result.record);
}

}  // namespace twinraster::cli
