// `twinraster render SCENE...`: parses the arguments, runs each scene (run/run_scene.hpp: the
// draws, the comparison, the judgement, the verdict), writes its PNGs (staged: all of a scene's or
// none, or one PNG to standard output), prints its record, and writes the batch's page and JUnit
// file. Several scenes share one GPU process and write into one directory.
#include "base/serial_queue.hpp"
#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
#include "book/book_renderer.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "cli/parser_setup.hpp"
#include "cli/progress.hpp"
#include "cli/scene_choice_options.hpp"
#include "cpu/cpu_renderer.hpp"
#include "image/png_file.hpp"
#include "image/thumbnail.hpp"
#include "report/batch_page.hpp"
#include "report/image_notes.hpp"
#include "report/junit.hpp"
#include "report/render_outputs.hpp"
#include "run/run_scene.hpp"
#include "scene/scene_error.hpp"
#include "twin_rules/lavapipe_path.hpp"
#include "twin_rules/twin_rules.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <set>

namespace twinraster {

namespace {

// About 11.6 days: any scene's limit, and a wait in milliseconds that fits an int.
constexpr int kMaxTimeoutSeconds = 1'000'000;

struct RenderArguments {
  std::vector<std::string> scenes;
  std::optional<std::string> output;     // one scene: OUT.png, - or a directory; several: a directory
  std::optional<std::string> directory;  // where each scene's files go, named after it (CheckOutput)
  int png_level = kPngFastest;
  std::string backend = "both";
  bool backend_given = false;  // --backend on the command line, rather than the default
  std::string rules = "vulkan";
  bool wireframe = false;  // --wireframe: as if every scene said "wireframe": true
  bool verify = false;     // --verify: judge the image just drawn by what Vulkan allows
  bool json = false;
  std::string device;
  double timeout_seconds = 600;  // the GPU process's time limit; 0: none
  unsigned threads = 0;
  bool quiet = false;
  std::optional<std::string> report;  // --report DIR: index.html and thumbnails
  std::optional<std::string> junit;   // --junit FILE
  SceneChoiceArguments choice;        // --camera, --scene, --size
  run::RunOptions run;                // the words above as the run stage takes them (ResolveOptions)
};

// The run's typed options, from the words parsed; every later step reads these. --rules book draws
// on the CPU only, so it implies --backend cpu; asking for another is a mistake.
void ResolveOptions(RenderArguments& a) {
  a.run.backends = a.backend == "gpu"   ? run::Backends::kGpu
                   : a.backend == "cpu" ? run::Backends::kCpu
                                        : run::Backends::kBoth;
  a.run.rules = a.rules == "book" ? run::Rules::kBook : run::Rules::kVulkan;
  a.run.verify = a.verify;
  a.run.threads = a.threads;
  a.run.device = a.device;
  if (a.run.rules != run::Rules::kBook) {
    // A device asked for decides the twin's rules; with no device to open, its name must say which.
    if (a.run.backends == run::Backends::kCpu && !a.device.empty())
      twin_rules::ChooseTwinRulesByName(a.device, twin_rules::DetectCpuPath());
    return;
  }
  if (a.verify)
    throw UsageError("--verify judges by Vulkan's rules, and --rules book draws by the demos': drop one of them");
  if (!a.device.empty())
    throw UsageError("--device chooses Vulkan's rules, and --rules book draws by the demos': drop one of them");
  if (a.backend_given && a.run.backends != run::Backends::kCpu) {
    throw UsageError("--rules book draws on the CPU only, as the chapter's demos do: drop --backend " + a.backend);
  }
  a.run.backends = run::Backends::kCpu;
}

// A name that ends in .png (in any case) and so looks like one file, not a directory of several.
bool LooksLikePng(const std::string& name) {
  std::string end = name.size() > 4 ? name.substr(name.size() - 4) : "";
  std::transform(end.begin(), end.end(), end.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return end == ".png";
}

// Several scenes: -o is a directory (default .), and each scene's files are named after it.
void CheckSeveralScenes(RenderArguments& a) {
  std::set<std::string> names;
  for (const std::string& scene : a.scenes) {
    if (IsStandardStream(scene)) throw UsageError("SCENE - (standard input) can only be rendered on its own");
    const std::string name = std::filesystem::path(scene).stem().string();
    if (!names.insert(name).second) {
      throw UsageError("two scenes are named \"" + name +
                       "\": their images would overwrite each other; render them "
                       "in separate calls");
    }
  }
  if (a.output && IsStandardStream(*a.output))
    throw UsageError("-o -: several scenes make several PNGs; give a directory");
  std::error_code ignored;
  if (a.output && std::filesystem::exists(*a.output, ignored) && !std::filesystem::is_directory(*a.output, ignored)) {
    throw UsageError("-o " + *a.output + ": with several scenes, -o names a directory, and this is a file");
  }
  // multi.png would become a directory of PNGs: almost surely a slip for one scene's file name.
  if (a.output && !NamesDirectory(*a.output) && LooksLikePng(*a.output)) {
    throw UsageError("-o " + *a.output + ": several scenes are written into a directory, and this names a PNG; give " +
                     "a directory (-o " + a.output->substr(0, a.output->size() - 4) + "/), or " + *a.output +
                     "/ for a directory of that name");
  }
  a.directory = a.output.value_or(".");
}

// Every check on the arguments that needs no scene and no device, so that a mistake costs nothing.
void CheckOutput(RenderArguments& a) {
  if (a.report && IsStandardStream(*a.report))
    throw UsageError("--report -: the report is a directory (index.html and thumbs/); give a directory");
  if (a.junit && IsStandardStream(*a.junit)) {
    if (a.json) throw UsageError("--junit - and --json both want standard output: drop one of them");
    if (a.output && IsStandardStream(*a.output))
      throw UsageError("--junit - and -o - both want standard output: give one of them a file");
  }
  if (a.scenes.size() > 1) return CheckSeveralScenes(a);
  const std::string& scene = a.scenes.front();
  if (IsStandardStream(scene) && !a.output) {
    throw UsageError("SCENE - (standard input) needs -o OUT.png, or -o - for the PNG on standard output");
  }
  if (!a.output || !IsStandardStream(*a.output)) {
    // -o DIR/ or an existing directory: the scene's files go there, named after it, as in a batch.
    if (a.output && NamesDirectory(*a.output)) {
      if (IsStandardStream(scene))
        throw UsageError("-o " + *a.output + ": SCENE - (standard input) has no name for its files; give -o OUT.png");
      a.directory = *a.output;
    } else if (a.output) {
      ExpectPngName("-o", *a.output);
    }
    return;
  }
  if (a.run.backends == run::Backends::kBoth) {
    throw UsageError(
        "-o - writes one PNG to standard output, and --backend both makes two: add --backend gpu or "
        "--backend cpu, or give -o OUT.png");
  }
  if (a.json) throw UsageError("-o - and --json both want standard output: drop one of them");
  if (a.report) throw UsageError("-o - writes no PNG file for --report's page to show: give -o OUT.png");
  if (StandardOutputIsTerminal()) {
    throw UsageError("-o -: standard output is a terminal; redirect it (> out.png) or pipe it to another program");
  }
}

// A scene's PNG (or the stem of its PNGs): in the directory, -o OUT.png, - or the scene's name.
std::string SceneOut(const RenderArguments& a, const std::string& scene_argument) {
  const std::string name = std::filesystem::path(scene_argument).stem().string() + ".png";
  return a.directory ? (std::filesystem::path(*a.directory) / name).string() : a.output.value_or(name);
}

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

// Every destination checked (docs/commands.md, "Output paths") and its missing directories made,
// before any scene is read or the GPU process started.
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

// A report shows the map of every judgement; --verify asks for it; -o - has nowhere to put it.
run::RunOptions RunOptionsOf(const RenderArguments& a, bool to_stdout) {
  run::RunOptions options = a.run;
  options.map = (a.verify || a.report) && !to_stdout;
  return options;
}

// Thumbnails for the batch page, staged with the scene's other files.
void StageThumbnails(const run::RunResult& result, const std::string& report_dir, std::vector<StagedFile>& staged) {
  const run::RunRecord& record = result.record;
  std::vector<std::pair<report::ImageKind, const Image*>> images;
  for (std::size_t i = 0; i < record.backends.size(); ++i) {
    const bool gpu = record.backends[i].backend == run::Backend::kGpu;
    images.emplace_back(gpu ? report::ImageKind::kGpu : report::ImageKind::kCpu, &result.images[i]);
  }
  if (result.diff) images.emplace_back(report::ImageKind::kDiff, &*result.diff);
  if (result.map) images.emplace_back(report::ImageKind::kMap, &*result.map);
  for (const auto& [kind, image] : images) {
    if (report::FullImage(record, kind).empty()) continue;
    const std::filesystem::path file = std::filesystem::path(report_dir) / report::ThumbnailPath(record, kind);
    const bool marks =
        kind == report::ImageKind::kDiff || kind == report::ImageKind::kMap;  // keep saturated marks visible
    staged.push_back(StagePng(file, Thumbnail(*image, report::kThumbnailSide,
                                              marks ? ThumbnailFilter::kMostSaturated : ThumbnailFilter::kMean)));
  }
}

// Names and encodes every image of the run, each staged in full before any is renamed into place
// (or, for -o -, kept for standard output), and records the files in the run's record.
std::vector<StagedFile> StageImages(run::RunResult& result, const RenderArguments& a, const std::string& out,
                                    std::string& png_bytes) {
  run::RunRecord& record = result.record;
  const bool to_stdout = IsStandardStream(out);
  std::vector<StagedFile> staged;
  for (std::size_t i = 0; i < record.backends.size(); ++i) {
    run::BackendRecord& backend = record.backends[i];
    if (!backend.Drawn()) continue;
    backend.output = a.run.backends == run::Backends::kBoth ? Suffixed(out, backend.Name()) : out;
    Stopwatch clock;
    const PngNotes notes = report::NotesOf(result.drawn_by[i]);
    if (to_stdout)
      png_bytes = EncodePng(result.images[i], a.png_level, notes);
    else
      staged.push_back(StagePng(backend.output, result.images[i], a.png_level, notes));
    backend.png_ms = clock.Milliseconds();
  }
  if (result.diff) {
    record.diff = Suffixed(out, "diff");
    staged.push_back(StagePng(record.diff, *result.diff, a.png_level));
  }
  if (result.map) {
    record.map = Suffixed(record.Find(*record.judged)->output, "map");
    staged.push_back(StagePng(record.map, *result.map, a.png_level));
  }
  if (a.report) StageThumbnails(result, *a.report, staged);
  return staged;
}

// A scene read and drawn, its files not yet written.
struct DrawnScene {
  run::RunResult result;
  std::string out;  // its PNG (or the stem of its PNGs), or - for standard output
  Stopwatch clock;  // since the scene began to be read
};

// Reads one scene and runs it: everything is drawn before anything is written, so that a run that
// fails writes no file at all.
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
  for (StagedFile& file : StageImages(result, a, drawn.out, png_bytes)) file.Commit();
  // A diff left by an earlier run would now describe images that no longer exist.
  std::error_code ignored;
  const std::string old_diff = Suffixed(drawn.out, "diff");
  if (!IsStandardStream(drawn.out) && !result.diff && result.record.comparison &&
      std::filesystem::is_regular_file(old_diff, ignored)) {
    std::filesystem::remove(old_diff, ignored);
  }
  progress.Clear();
  if (!png_bytes.empty()) WriteStandardOutput(png_bytes);
  result.record.total_ms = drawn.clock.Milliseconds();
  return std::move(result.record);
}

// Prints one scene's record: JSON (one object; several scenes: JSON Lines, one per scene as it
// finishes) or the report's lines (on standard error when the PNG goes to standard output).
void PrintRecord(const RenderArguments& a, const run::RunRecord& record, bool several) {
  if (a.json) {
    std::cout << (several ? report::RenderJson(record).dump() : report::RenderJson(record).dump(2)) << "\n"
              << std::flush;
    return;
  }
  // Standard output carries the PNG (-o -) or the JUnit XML (--junit -) alone.
  const bool to_stdout =
      (!several && a.output && IsStandardStream(*a.output)) || (a.junit && IsStandardStream(*a.junit));
  if (to_stdout && a.quiet) return;
  (to_stdout ? std::cerr : std::cout) << report::RenderText(record, a.verify) << std::flush;
}

// The page and the JUnit file, staged together after the batch: all of them or neither.
void WriteBatchReports(const RenderArguments& a, const std::vector<run::RunRecord>& records, double total_ms) {
  std::vector<StagedFile> staged;
  if (a.report) {
    staged.emplace_back(std::filesystem::path(*a.report) / "index.html",
                        report::BatchPageHtml(records, *a.report, total_ms));
  }
  const bool junit_to_stdout = a.junit && IsStandardStream(*a.junit);
  if (a.junit && !junit_to_stdout) staged.emplace_back(*a.junit, report::JUnitXml(records, total_ms, a.verify));
  for (StagedFile& file : staged) file.Commit();
  if (junit_to_stdout) WriteStandardOutput(report::JUnitXml(records, total_ms, a.verify));
}

// Whether a scene's failure is its own (bad input, an output that cannot be written), which a batch
// reports and goes on from, rather than the run's.
bool SceneOwnError(const std::exception& e) {
  return dynamic_cast<const SceneError*>(&e) || dynamic_cast<const FileError*>(&e);
}

// What a batch keeps of its scenes: the records for the page and JUnit file, and the worst exit.
struct BatchTally {
  std::vector<run::RunRecord> records;
  int worst = kExitOk;
  void Add(const RenderArguments& a, run::RunRecord record) {
    worst = WorseExit(worst, ExitCodeOf(record.verdict));
    if (a.report || a.junit) records.push_back(std::move(record));
  }
};

// A scene that failed on its own: said on standard error, and a record of verdict error, which
// --json prints as any other scene's (so that every scene has its line) and the batch keeps.
void FailedScene(const RenderArguments& a, const std::string& scene, const std::exception& e, Progress& progress,
                 BatchTally& tally, bool several) {
  run::RunRecord record = run::ErrorRecord(scene, e.what());
  record.rules = a.run.rules;
  progress.Above([&] {
    std::cerr << "twinraster: " << e.what() << "\n";
    if (a.json) PrintRecord(a, record, several);
  });
  tally.Add(a, std::move(record));
}

// One scene at a time: read, draw, write, print. One scene's bad input is the run's error (exit 2,
// nothing written), unless a report, a JUnit file or JSON is asked for, which then records it.
void RenderInTurn(const RenderArguments& a, run::GpuSession& gpu, Progress& progress, BatchTally& tally) {
  const bool keep_going = a.report || a.junit || a.json;
  for (const std::string& scene : a.scenes) {
    try {
      DrawnScene drawn = DrawScene(a, scene, gpu, progress);
      run::RunRecord record = WriteScene(a, drawn, progress);
      PrintRecord(a, record, false);
      tally.Add(a, std::move(record));
    } catch (const std::exception& e) {
      if (!SceneOwnError(e) || !keep_going) throw;
      FailedScene(a, scene, e, progress, tally, false);
    }
  }
}

// Several scenes, each on its own: a bad scene or an unwritable output is reported and the others
// still render. Each scene's files are written and its record printed on a thread of its own, in
// order, while the next scene draws: the PNGs and the file system's waits take the other core.
// `writer` is idle whenever the GPU process forks (Render sets that up).
void RenderBatch(const RenderArguments& a, run::GpuSession& gpu, Progress& progress, BatchTally& tally,
                 SerialQueue& writer) {
  for (const std::string& scene : a.scenes) {
    try {
      auto drawn = std::make_shared<DrawnScene>(DrawScene(a, scene, gpu, progress));
      writer.Push([&a, &progress, &tally, scene, drawn] {
        try {
          run::RunRecord record = WriteScene(a, *drawn, progress);
          progress.Above([&] { PrintRecord(a, record, true); });
          tally.Add(a, std::move(record));
        } catch (const std::exception& e) {
          if (!SceneOwnError(e)) throw;
          FailedScene(a, scene, e, progress, tally, true);
        }
      });
    } catch (const std::exception& e) {
      if (!SceneOwnError(e)) throw;  // the queue's scenes are still written first
      const std::string what = e.what();
      writer.Push([&progress, &tally, &a, scene, what] {
        FailedScene(a, scene, std::runtime_error(what), progress, tally, true);
      });
    }
  }
  writer.Finish();
}

int Render(RenderArguments& a) {
  ResolveOptions(a);
  CheckOutput(a);
  PrepareDestinations(a);
  Progress progress = Progress::OnStandardError(a.quiet);
  const bool several = a.scenes.size() > 1;
  SerialQueue writer(2);  // several scenes: each written while the next draws; each waiting holds its images
  IsolationOptions isolation;
  isolation.gpu.device = a.device;
  isolation.timeout_seconds = a.timeout_seconds;
  if (several) isolation.before_fork = [&writer] { writer.WaitIdle(); };
  run::GpuSession gpu(isolation);  // a child process, made for the first GPU draw and kept
  // The exit code is the worst of the scenes'. No Vulkan device ends the run (exit 3).
  Stopwatch batch_clock;
  BatchTally tally;
  if (several) {
    RenderBatch(a, gpu, progress, tally, writer);
  } else {
    RenderInTurn(a, gpu, progress, tally);
  }
  WriteBatchReports(a, tally.records, batch_clock.Milliseconds());
  return tally.worst;
}

}  // namespace

CommandRun AddRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* command = AddSubcommand(
      app, "render", "draw a scene on Vulkan, on the CPU twin, or on both and compare; or as the book's demos do",
      "Each PNG is written whole to a temporary file and renamed into place: a failed run leaves\n"
      "earlier files untouched, and a read-only file is never replaced. Every output is checked\n"
      "before anything is drawn. On a terminal, progress shows on standard error.\n"
      "The Vulkan work runs in a child process: when the driver crashes or passes --timeout, the\n"
      "report says so, the twin's image is still written, and later scenes still render.\n"
      "Exit codes: 0 done (both: identical images, or different where the twin has no rules for\n"
      "the driver and the verifier passes the GPU's), 1 the images differ (or --verify found a\n"
      "violation), 2 bad input or usage,\n"
      "3 no usable Vulkan device (--backend cpu needs none), 4 internal error, 5 the Vulkan\n"
      "driver crashed or timed out (the twin's image and the report were still written), 6 the\n"
      "verifier found no violation but could not tell a broken image (inconclusive).");
  command
      ->add_option("SCENE", a->scenes,
                   "scene files (JSON), OBJ meshes (.obj: framed, lit by a headlight), glTF 2.0\n"
                   "files (.gltf, .glb: their camera, or framed), or - to read one scene from\n"
                   "standard input")
      ->required();
  command
      ->add_option("-o,--output", a->output,
                   "gpu, cpu: write OUT.png; both: OUT-gpu.png, OUT-cpu.png and, when\n"
                   "they differ, OUT-diff.png. Default: the scene's name in the current\n"
                   "directory. - writes the PNG to standard output (gpu or cpu only).\n"
                   "DIR/ (a final /) or an existing directory, and with several scenes any\n"
                   "name but OUT.png (default .): each scene's files go there, named after it.\n"
                   "Missing directories are made, for every option that writes")
      ->type_name("OUT.png|DIR");
  ExpectIntegerIn(command
                      ->add_option("--png-level", a->png_level,
                                   "PNG compression, 0 (none) to 12 (smallest, slowest); default 1, the fastest")
                      ->type_name("0-12"),
                  0, 12);
  CLI::Option* backend =
      ExpectOneOf(command->add_option("--backend", a->backend, "where to draw (default: both; with --rules book, cpu)")
                      ->type_name("gpu|cpu|both"),
                  "backend", {"gpu", "cpu", "both"});
  ExpectOneOf(command
                  ->add_option("--rules", a->rules,
                               "vulkan (default): filled triangles, depth-tested and clipped, by Vulkan's\n"
                               "rules. book: wireframes drawn as the chapter's live demos draw them\n"
                               "(truncated coordinates, no clipping, no depth), on the CPU only")
                  ->type_name("vulkan|book"),
              "rule set", {"vulkan", "book"});
  command->add_flag("--wireframe", a->wireframe,
                    "draw triangle edges only (Vulkan's polygonMode LINE, 1 pixel, depth-tested), as\n"
                    "if the scene said \"wireframe\": true; the twin follows the device's line rules");
  command->add_flag("--verify", a->verify,
                    "judge the image drawn (the GPU's, if drawn) by what a conformant Vulkan\n"
                    "implementation may draw, pixel by pixel (docs/verify.md), and write its\n"
                    "map beside it as OUT-map.png (OUT-gpu-map.png with both); exit 1 on a\n"
                    "violation. Without it, a difference between the two images is still judged");
  command->add_flag("--json", a->json, "print the report as JSON (twinraster.render/5, docs/json-output.md)");
  command
      ->add_option("--device", a->device,
                   "the Vulkan device to draw on, whose rules the twin follows: lavapipe (default),\n"
                   "swiftshader, or any part of a device's full name, in any case (--version lists\n"
                   "them). --backend cpu opens none: the name alone chooses the twin's rules, and\n"
                   "one it has none for is refused")
      ->type_name("NAME");
  // The bound keeps the GPU process's wait, in milliseconds, inside an int (poll's timeout).
  ExpectNumberIn(command
                     ->add_option("--timeout", a->timeout_seconds,
                                  "seconds the Vulkan driver may take for one scene before it is stopped and\n"
                                  "the scene reported as timed out (default 600; 0: no limit; at most 1000000)")
                     ->type_name("SECONDS"),
                 0, kMaxTimeoutSeconds, "seconds from 0 (no limit) to " + std::to_string(kMaxTimeoutSeconds));
  ExpectIndex(command
                  ->add_option("--threads", a->threads,
                               "the CPU twin's threads, at most one per 16 rows (default: every core for a\n"
                               "frame of over " +
                                   std::to_string(cpu::kOneThreadPixels) + " pixels or over " +
                                   std::to_string(cpu::kOneThreadTriangles) +
                                   " triangles, counting every\n"
                                   "instance's; one for a smaller frame, where another costs more than it saves)")
                  ->type_name("N"));
  AddSceneChoiceOptions(*command, a->choice);
  command->add_flag("-q,--quiet", a->quiet, "no progress on standard error (and, with -o -, no report)");
  command
      ->add_option("--report", a->report,
                   "also write DIR/index.html: one page for the batch, failures first, each scene's\n"
                   "images as thumbnails (DIR/thumbs/) with its verdict, counts, device and times;\n"
                   "every verification's map is written too")
      ->type_name("DIR");
  command
      ->add_option("--junit", a->junit,
                   "also write the batch as JUnit XML (one testcase per scene) to FILE; - writes it\n"
                   "to standard output, and the report to standard error")
      ->type_name("FILE");
  return [a, backend] {
    a->backend_given = backend->count() > 0;
    return Render(*a);
  };
}

}  // namespace twinraster
