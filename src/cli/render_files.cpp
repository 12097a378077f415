#include "cli/render_files.hpp"

#include "base/stopwatch.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "files/png_file.hpp"
#include "image/thumbnail.hpp"
#include "run_report/batch_page.hpp"
#include "run_report/image_notes.hpp"
#include "run_report/junit.hpp"

#include <filesystem>
#include <utility>

namespace twinraster::cli {

namespace {

// Every file a scene may write at `out` (StageImages names them): its image or images, their
// maps (which backend is judged is known only after the draw), the diff.
std::vector<std::string> SceneFiles(const RenderArguments& a, const std::string& out) {
  const bool both = a.run.backends == run::Backends::kBoth;
  std::vector<std::string> files;
  for (const std::string& image : both ? std::vector{Suffixed(out, "gpu"), Suffixed(out, "cpu")} : std::vector{out}) {
    files.push_back(image);
    if (a.verify || a.report) files.push_back(Suffixed(image, "map"));
  }
  if (both) files.push_back(Suffixed(out, "diff"));
  return files;
}

// Thumbnails for the batch page, staged with the scene's other files.
void StageThumbnails(const run::RunResult& result, const std::string& report_dir,
                     std::vector<files::StagedFile>& staged) {
  const run::RunRecord& record = result.record;
  std::vector<std::pair<run_report::ImageKind, const Image*>> images;
  for (std::size_t i = 0; i < record.backends.size(); ++i) {
    const bool gpu = record.backends[i].backend == run::Backend::kGpu;
    images.emplace_back(gpu ? run_report::ImageKind::kGpu : run_report::ImageKind::kCpu, &result.images[i]);
  }
  if (result.diff) images.emplace_back(run_report::ImageKind::kDiff, &*result.diff);
  if (result.map) images.emplace_back(run_report::ImageKind::kMap, &*result.map);
  for (const auto& [kind, image] : images) {
    if (run_report::FullImage(record, kind).empty()) continue;
    const std::filesystem::path file = std::filesystem::path(report_dir) / run_report::ThumbnailPath(record, kind);
    const bool marks =
        kind == run_report::ImageKind::kDiff || kind == run_report::ImageKind::kMap;  // keep saturated marks visible
    staged.push_back(
        files::StagePng(file, Thumbnail(*image, run_report::kThumbnailSide,
                                        marks ? ThumbnailFilter::kMostSaturated : ThumbnailFilter::kMean)));
  }
}

}  // namespace

std::string SceneOut(const RenderArguments& a, const std::string& scene_argument) {
  const std::string name = std::filesystem::path(scene_argument).stem().string() + ".png";
  return a.directory ? (std::filesystem::path(*a.directory) / name).string() : a.output.value_or(name);
}

void PrepareDestinations(const RenderArguments& a) {
  OutputPaths paths;
  const std::string option = "-o " + a.output.value_or(".");
  if (a.directory) paths.Directory(option, *a.directory);
  for (const std::string& scene : a.scenes) {
    const std::string out = SceneOut(a, scene);
    if (IsStandardStream(out)) continue;
    for (const std::string& file : SceneFiles(a, out)) paths.File(a.output ? option : "SCENE " + scene, file);
  }
  if (a.report) {
    paths.Directory("--report " + *a.report, *a.report);
    paths.Directory("--report " + *a.report, std::filesystem::path(*a.report) / "thumbs");
    paths.File("--report " + *a.report, std::filesystem::path(*a.report) / "index.html");
  }
  if (a.junit && !IsStandardStream(*a.junit)) paths.File("--junit " + *a.junit, *a.junit);
  paths.MakeDirectories();
}

std::vector<files::StagedFile> StageImages(run::RunResult& result, const RenderArguments& a, const std::string& out,
                                           std::string& png_bytes) {
  run::RunRecord& record = result.record;
  const bool to_stdout = IsStandardStream(out);
  std::vector<files::StagedFile> staged;
  for (std::size_t i = 0; i < record.backends.size(); ++i) {
    run::BackendRecord& backend = record.backends[i];
    if (!backend.Drawn()) continue;
    backend.output = a.run.backends == run::Backends::kBoth ? Suffixed(out, backend.Name()) : out;
    Stopwatch clock;
    const files::PngNotes notes = run_report::NotesOf(result.drawn_by[i]);
    if (to_stdout)
      png_bytes = files::EncodePng(result.images[i], a.png_level, notes);
    else
      staged.push_back(files::StagePng(backend.output, result.images[i], a.png_level, notes));
    backend.png_ms = clock.Milliseconds();
  }
  if (result.diff) {
    record.diff = Suffixed(out, "diff");
    staged.push_back(files::StagePng(record.diff, *result.diff, a.png_level));
  }
  if (result.map) {
    record.map = Suffixed(record.Find(*record.judged)->output, "map");
    staged.push_back(files::StagePng(record.map, *result.map, a.png_level));
  }
  if (a.report) StageThumbnails(result, *a.report, staged);
  return staged;
}

void RemoveStaleDiff(const run::RunResult& result, const std::string& out) {
  std::error_code ignored;
  const std::string old_diff = Suffixed(out, "diff");
  if (!IsStandardStream(out) && !result.diff && result.record.comparison &&
      std::filesystem::is_regular_file(old_diff, ignored)) {
    std::filesystem::remove(old_diff, ignored);
  }
}

void WriteBatchReports(const RenderArguments& a, const run::BatchResult& batch) {
  std::vector<files::StagedFile> staged;
  if (a.report)
    staged.emplace_back(std::filesystem::path(*a.report) / "index.html", run_report::BatchPageHtml(batch, *a.report));
  const bool junit_to_stdout = a.junit && IsStandardStream(*a.junit);
  if (a.junit && !junit_to_stdout) staged.emplace_back(*a.junit, run_report::JUnitXml(batch, a.verify));
  for (files::StagedFile& file : staged) file.Commit();
  if (junit_to_stdout) WriteStandardOutput(run_report::JUnitXml(batch, a.verify));
}

}  // namespace twinraster::cli
