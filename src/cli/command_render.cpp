// `twinraster render SCENE...`: draws each scene on lavapipe, on the CPU twin or both, or (--rules
// book) as the chapter's demos draw it; writes the PNGs (staged: all of a scene's or none, or one
// PNG to standard output) and compares the images. The Vulkan work runs in a child process, which
// several scenes share (with its device and pipeline) until the driver crashes; they write into
// one directory.
#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
#include "book/book_renderer.hpp"
#include "chain/draw_list.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/parser_setup.hpp"
#include "cli/progress.hpp"
#include "cpu/cpu_renderer.hpp"
#include "cpu/lavapipe_path.hpp"
#include "cpu/twin_rules.hpp"
#include "gpu/gpu_renderer.hpp"
#include "gpu/isolated_gpu.hpp"
#include "image/image_compare.hpp"
#include "image/png_file.hpp"
#include "image/thumbnail.hpp"
#include "report/batch_page.hpp"
#include "report/comparison_report.hpp"
#include "report/image_notes.hpp"
#include "report/junit.hpp"
#include "report/render_outputs.hpp"
#include "report/render_record.hpp"
#include "report/verify_report.hpp"
#include "cpu/triangle_setup.hpp"
#include "scene/scene_error.hpp"
#include "verify/verifier.hpp"
#include "verify/verify_map.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <iostream>
#include <set>
#include <memory>
#include <optional>
#include <sstream>

namespace twinraster {

namespace {

struct RenderArguments {
  std::vector<std::string> scenes;
  std::optional<std::string> output;  // one scene: OUT.png or -; several: a directory
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
};

// A backend's record and the image it drew, until the PNGs are written.
struct BackendRun : report::BackendRecord {
  Image image;
};

// Who drew a backend's image and how that device rasterizes: the judgement's rules and the
// image's PNG notes. The twin draws lines as lavapipe does, strictly, at its subpixel precision.
report::DrawnBy DrawnByOf(const BackendRun& run, const DeviceIdentity& device) {
  if (run.name == "gpu") {
    return {device.name, {.subpixel_bits = int(device.subpixel_bits), .strict_lines = device.strict_lines}};
  }
  return {"CPU twin", {.subpixel_bits = cpu::kSubpixelBits, .strict_lines = true}};
}

// The Vulkan work runs in a child process (gpu/isolated_gpu.hpp): a driver that crashes or hangs
// costs this scene its GPU image, not the run. The child and its device serve every scene of a
// batch until one crashes; the next scene then gets a fresh one.
BackendRun RenderGpu(const DrawList& list, const RenderArguments& a, const std::string& scene_argument,
                     std::optional<GpuProcess>& gpu, Progress& progress, DeviceIdentity& device) {
  BackendRun run;
  run.name = "gpu";
  progress.Status("gpu: drawing on Vulkan...");
  if (!gpu) {
    IsolationOptions options;
    options.gpu.device = a.device;
    options.timeout_seconds = a.timeout_seconds;
    gpu.emplace(options);
  }
  IsolatedGpuResult r = gpu->Render(list);
  device = r.device;
  run.detail = r.device.name.empty() ? "no device" : r.device.name;
  run.driver = r.device.driver_info;
  switch (r.outcome) {
    case GpuOutcome::kRendered:
      break;
    case GpuOutcome::kUnavailable:
      throw GpuUnavailable(r.problem);  // exit 3, as before any child existed
    case GpuOutcome::kBadList:
      throw std::invalid_argument(r.problem);
    case GpuOutcome::kCrashed:
    case GpuOutcome::kTimedOut:
      run.status = r.outcome == GpuOutcome::kCrashed ? "crashed" : "timed out";
      run.problem = r.problem + " on " + (IsStandardStream(scene_argument) ? "<stdin>" : scene_argument);
      return run;
  }
  run.image = std::move(r.image);
  // Set-up is everything before the draw: instance, device and pipeline, then buffers.
  run.setup_ms = r.device_ms + r.timings.setup_ms, run.draw_ms = r.timings.draw_ms;
  run.readback_ms = r.timings.readback_ms, run.isolation_ms = r.isolation_ms;
  return run;
}

BackendRun RenderCpu(const DrawList& list, unsigned threads, const cpu::RasterRules& rules, Progress& progress) {
  BackendRun run;
  run.name = "cpu";
  progress.Status("cpu: drawing...");
  CpuOptions options;
  options.threads = threads;
  options.rules = rules;
  CpuTimings t;
  run.image = RenderOnCpu(list, options, &t);
  run.detail = "CPU twin, " + std::to_string(t.threads) + (t.threads == 1 ? " thread" : " threads");
  run.setup_ms = t.setup_ms, run.draw_ms = t.draw_ms, run.readback_ms = t.readback_ms;
  return run;
}

// The chapter's demos draw on one thread, straight into the image: all of it is drawing.
BackendRun RenderBook(const Scene& scene, const std::string& scene_argument, Progress& progress) {
  BackendRun run;
  run.name = "cpu", run.detail = "book rules: the chapter's demos, 1 thread";
  progress.Status("cpu: drawing by the book's rules...");
  Stopwatch clock;
  try {
    run.image = book::RenderScene(scene);
  } catch (const book::BookRulesError& e) {
    // Reported as a problem with the scene, like the loader's, so that several scenes go on.
    throw SceneError(IsStandardStream(scene_argument) ? "<stdin>" : scene_argument, e.where(),
                     "--rules book: " + e.problem());
  }
  run.draw_ms = clock.Milliseconds();
  return run;
}

// --rules book draws on the CPU only, so it implies --backend cpu; asking for another is a mistake.
void ResolveRules(RenderArguments& a) {
  if (a.rules != "book") return;
  if (a.verify) throw UsageError("--verify judges by Vulkan's rules, and --rules book draws by the demos': drop one of them");
  if (a.backend_given && a.backend != "cpu") {
    throw UsageError("--rules book draws on the CPU only, as the chapter's demos do: drop --backend " + a.backend);
  }
  a.backend = "cpu";
}

// Every check on the arguments that needs no scene and no device, so that a mistake costs nothing.
void CheckOutput(const RenderArguments& a) {
  if (a.scenes.size() > 1) {
    // Several scenes: -o is a directory, and each scene's files are named after it.
    std::set<std::string> names;
    for (const std::string& scene : a.scenes) {
      if (IsStandardStream(scene)) throw UsageError("SCENE - (standard input) can only be rendered on its own");
      const std::string name = std::filesystem::path(scene).stem().string();
      if (!names.insert(name).second) {
        throw UsageError("two scenes are named \"" + name + "\": their images would overwrite each other; render them "
                         "in separate calls");
      }
    }
    if (a.output && IsStandardStream(*a.output)) throw UsageError("-o -: several scenes make several PNGs; give a directory");
    std::error_code ignored;
    if (a.output && std::filesystem::exists(*a.output, ignored) && !std::filesystem::is_directory(*a.output, ignored)) {
      throw UsageError("-o " + *a.output + ": with several scenes, -o names a directory, and this is a file");
    }
    return;
  }
  const std::string& scene = a.scenes.front();
  if (IsStandardStream(scene) && !a.output) {
    throw UsageError("SCENE - (standard input) needs -o OUT.png, or -o - for the PNG on standard output");
  }
  if (!a.output || !IsStandardStream(*a.output)) {
    if (a.output) ExpectPngName("-o", *a.output);
    std::error_code ignored;
    if (a.output && std::filesystem::is_directory(*a.output, ignored)) {
      throw UsageError("-o " + *a.output + ": give a file name (OUT.png), not a directory");
    }
    return;
  }
  if (a.backend == "both") {
    throw UsageError("-o - writes one PNG to standard output, and --backend both makes two: add --backend gpu or "
                     "--backend cpu, or give -o OUT.png");
  }
  if (a.json) throw UsageError("-o - and --json both want standard output: drop one of them");
  if (a.report) throw UsageError("-o - writes no PNG file for --report's page to show: give -o OUT.png");
  if (StandardOutputIsTerminal()) {
    throw UsageError("-o -: standard output is a terminal; redirect it (> out.png) or pipe it to another program");
  }
}

// Thumbnails for the batch page, staged with the scene's other files.
void StageThumbnails(const report::RenderRecord& record, const std::string& report_dir,
                     const std::vector<std::pair<std::string, const Image*>>& images, std::vector<StagedFile>& staged) {
  for (const auto& [kind, image] : images) {
    if (report::FullImage(record, kind).empty()) continue;
    const std::filesystem::path file = std::filesystem::path(report_dir) / report::ThumbnailPath(record, kind);
    const bool marks = kind == "diff" || kind == "map";  // saturated marks on grey: keep them visible
    staged.push_back(StagePng(file, Thumbnail(*image, report::kThumbnailSide,
                                              marks ? ThumbnailFilter::kMostSaturated : ThumbnailFilter::kMean)));
  }
}

// One scene, from reading it to its files and its record (which render prints, and the page and
// JUnit file read). `directory`: where several scenes' files go.
report::RenderRecord RenderScene(const RenderArguments& a, const std::string& scene_argument,
                                 const std::optional<std::string>& directory, std::optional<GpuProcess>& gpu,
                                 Progress& progress) {
  progress.Status("reading " + scene_argument + "...");
  Stopwatch total_clock;
  Stopwatch load_clock;
  Scene scene = LoadSceneArgument(scene_argument);
  if (a.wireframe) scene.wireframe = true;
  const std::string out = directory ? (std::filesystem::path(*directory) / (scene.name + ".png")).string()
                                    : a.output.value_or(scene.name + ".png");
  const bool to_stdout = IsStandardStream(out);
  const bool book = a.rules == "book";
  const DrawList list = book ? DrawList{} : BuildDrawList(scene);  // the book draws from the scene

  report::RenderRecord record;
  record.scene = scene_argument;
  record.name = scene.name;
  record.rules = a.rules;
  record.wireframe = book || scene.wireframe;  // the book's demos draw wireframes only
  record.width = scene.canvas.width, record.height = scene.canvas.height;
  record.instances = scene.instances.size();
  for (const Instance& instance : scene.instances) record.triangles += scene.models[instance.model].triangles.size();
  record.load_ms = load_clock.Milliseconds();

  // Render everything before writing anything: a run that fails writes no file at all. A GPU
  // process that crashes or times out is a result: the twin still draws and its image is written.
  std::vector<BackendRun> runs;
  DeviceIdentity device;
  if (book) {
    runs.push_back(RenderBook(scene, scene_argument, progress));
  } else {
    if (a.backend != "cpu") runs.push_back(RenderGpu(list, a, scene_argument, gpu, progress, device));  // GpuUnavailable: exit 3
    if (a.backend != "gpu") {
      // The twin copies the lavapipe that drew (or, with no device asked, its default release).
      record.twin = cpu::ChooseTwinRules(device.name, device.driver_info, cpu::DetectCpuPath());
      runs.push_back(RenderCpu(list, a.threads, record.twin->rules, progress));
    }
  }
  for (BackendRun& run : runs) {
    if (run.Drawn()) run.output = a.backend == "both" ? Suffixed(out, run.name) : out;
  }
  const bool gpu_failed = std::any_of(runs.begin(), runs.end(), [](const BackendRun& r) { return !r.Drawn(); });

  const std::string diff_file = to_stdout ? "" : Suffixed(out, "diff");
  if (runs.size() == 2 && !gpu_failed) {
    progress.Status("comparing gpu and cpu...");
    record.comparison = CompareImages(runs[0].image, runs[1].image);
  }
  const bool differ = record.comparison && !record.comparison->Equal();

  // The verifier judges the image drawn (the GPU's when there is one) when asked, and whenever the
  // two images differ, to say whether the difference is one Vulkan allows.
  const BackendRun* judged = nullptr;
  if (!book && (a.verify || differ)) {
    for (const BackendRun& run : runs) {
      if (run.Drawn() && (!judged || run.name == "gpu")) judged = &run;
    }
  }
  std::optional<Image> map;
  if (judged) {
    progress.Status("verifying the " + judged->name + " image...");
    Stopwatch clock;
    record.verification = verify::VerifyImage(scene, list, judged->image, DrawnByOf(*judged, device).rasterizes);
    record.verify_ms = clock.Milliseconds();
    record.judged = judged->name;
    // A report shows the map of every judgement; otherwise --verify asks for it.
    if ((a.verify || a.report) && !to_stdout) {
      record.map = Suffixed(judged->output, "map");
      map = verify::VerificationMap(judged->image, *record.verification);
    }
    record.verification->pixels = {};  // the map holds them; a batch's records stay small
  }

  // Every output is encoded and staged in full before any is renamed into place (or written out).
  progress.Status(runs.size() == 1 ? "writing the PNG..." : "writing the PNGs...");
  std::vector<StagedFile> staged;
  std::string png_bytes;  // for -o -
  for (BackendRun& run : runs) {
    if (!run.Drawn()) continue;
    Stopwatch clock;
    const PngNotes notes = report::NotesOf(DrawnByOf(run, device));
    if (to_stdout) png_bytes = EncodePng(run.image, a.png_level, notes);
    else staged.push_back(StagePng(run.output, run.image, a.png_level, notes));
    run.png_ms = clock.Milliseconds();
  }
  std::optional<Image> diff;
  if (differ) {
    record.diff = diff_file;
    diff = DiffImage(runs[0].image, runs[1].image);
    staged.push_back(StagePng(diff_file, *diff, a.png_level));
  }
  if (map) staged.push_back(StagePng(record.map, *map, a.png_level));
  for (const BackendRun& run : runs) record.backends.push_back(run);  // the record part, without the image
  if (a.report) {
    std::vector<std::pair<std::string, const Image*>> images;
    for (const BackendRun& run : runs) images.emplace_back(run.name, &run.image);
    if (diff) images.emplace_back("diff", &*diff);
    if (map) images.emplace_back("map", &*map);
    StageThumbnails(record, *a.report, images, staged);
  }
  for (StagedFile& file : staged) file.Commit();
  // A diff left by an earlier run would now describe images that no longer exist.
  std::error_code ignored;
  if (record.comparison && record.comparison->Equal() && std::filesystem::is_regular_file(diff_file, ignored)) {
    std::filesystem::remove(diff_file, ignored);
  }
  progress.Clear();
  if (to_stdout && !png_bytes.empty()) WriteStandardOutput(png_bytes);

  // The one verdict the page and the JUnit file show decides the exit code too.
  record.exit_code = ExitCodeOf(report::VerdictOf(record));
  record.total_ms = total_clock.Milliseconds();
  return record;
}

// Prints one scene's record: JSON (one object; several scenes: JSON Lines, one per scene as it
// finishes) or the report's lines (on standard error when the PNG goes to standard output).
void PrintRecord(const RenderArguments& a, const report::RenderRecord& record, bool several) {
  if (a.json) {
    std::cout << (several ? report::RenderJson(record).dump() : report::RenderJson(record).dump(2)) << "\n" << std::flush;
    return;
  }
  const bool to_stdout = !several && a.output && IsStandardStream(*a.output);
  if (to_stdout && a.quiet) return;
  (to_stdout ? std::cerr : std::cout) << report::RenderText(record, a.verify) << std::flush;
}

// The page and the JUnit file, staged together after the batch: all of them or neither.
void WriteBatchReports(const RenderArguments& a, const std::vector<report::RenderRecord>& records, double total_ms) {
  std::vector<StagedFile> staged;
  if (a.report) {
    staged.emplace_back(std::filesystem::path(*a.report) / "index.html",
                        report::BatchPageHtml(records, *a.report, total_ms));
  }
  if (a.junit) staged.emplace_back(*a.junit, report::JUnitXml(records, total_ms, a.verify));
  for (StagedFile& file : staged) file.Commit();
}

int Render(RenderArguments& a) {
  ResolveRules(a);
  CheckOutput(a);
  Progress progress = Progress::OnStandardError(a.quiet);
  std::optional<GpuProcess> gpu;
  const bool several = a.scenes.size() > 1;
  const std::optional<std::string> directory = several ? std::optional(a.output.value_or(".")) : std::nullopt;
  if (directory) MakeDirectory(*directory);
  if (a.report) MakeDirectory((std::filesystem::path(*a.report) / "thumbs").string());  // and DIR with it
  // One scene's bad input is the run's error (exit 2, nothing written), unless a report or JUnit
  // file is asked for, which then records it. Several scenes: each on its own; a bad scene, an
  // unwritable output or a crashed GPU process is reported and the others still render; the exit
  // code is the worst of them. No Vulkan device ends the run (exit 3).
  const bool keep_going = several || a.report || a.junit;
  Stopwatch batch_clock;
  std::vector<report::RenderRecord> records;
  int worst = kExitOk;
  for (const std::string& scene : a.scenes) {
    report::RenderRecord record;
    try {
      record = RenderScene(a, scene, directory, gpu, progress);
      PrintRecord(a, record, several);
    } catch (const std::exception& e) {
      const bool expected = dynamic_cast<const SceneError*>(&e) || dynamic_cast<const FileError*>(&e);
      if (!expected || !keep_going) throw;
      progress.Clear();
      std::cerr << "twinraster: " << e.what() << "\n";
      record = {};
      record.scene = scene;
      record.name = std::filesystem::path(scene).stem().string();
      record.error = e.what();
      record.exit_code = kExitBadInput;
    }
    worst = WorseExit(worst, record.exit_code);
    if (a.report || a.junit) records.push_back(std::move(record));
  }
  WriteBatchReports(a, records, batch_clock.Milliseconds());
  return worst;
}

}  // namespace

CommandRun AddRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* command = AddSubcommand(
      app, "render", "draw a scene on Vulkan, on the CPU twin, or on both and compare; or as the book's demos do",
      "Each PNG is written whole to a temporary file and renamed into place: a failed run leaves\n"
      "earlier files untouched. On a terminal, progress shows on standard error.\n"
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
                   "scene files (JSON) or OBJ meshes (.obj: framed, lit by a headlight), or - to\n"
                   "read one scene from standard input")
      ->required();
  command
      ->add_option("-o,--output", a->output,
                   "gpu, cpu: write OUT.png; both: OUT-gpu.png, OUT-cpu.png and, when\n"
                   "they differ, OUT-diff.png. Default: the scene's name in the current\n"
                   "directory. - writes the PNG to standard output (gpu or cpu only).\n"
                   "Several scenes: OUT is a directory (made if missing; default .) and\n"
                   "each scene's files are named after it")
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
                    "if the scene said \"wireframe\": true; the twin follows lavapipe's line rules");
  command->add_flag("--verify", a->verify,
                    "judge the image drawn (the GPU's, if drawn) by what a conformant Vulkan\n"
                    "implementation may draw, pixel by pixel (docs/verify.md), and write its\n"
                    "map beside it as OUT-map.png (OUT-gpu-map.png with both); exit 1 on a\n"
                    "violation. Without it, a difference between the two images is still judged");
  command->add_flag("--json", a->json, "print the report as JSON (twinraster.render/4, docs/json-output.md)");
  command->add_option("--device", a->device, "the Vulkan device whose name contains NAME (default: lavapipe)")
      ->type_name("NAME");
  command
      ->add_option("--timeout", a->timeout_seconds,
                   "seconds the Vulkan driver may take for one scene before it is stopped and\n"
                   "the scene reported as timed out (default 600; 0: no limit)")
      ->type_name("SECONDS")
      ->check(CLI::NonNegativeNumber);
  ExpectIndex(command->add_option("--threads", a->threads, "the CPU twin's threads (default: all cores)")->type_name("N"));
  command->add_flag("-q,--quiet", a->quiet, "no progress on standard error (and, with -o -, no report)");
  command
      ->add_option("--report", a->report,
                   "also write DIR/index.html: one page for the batch, failures first, each scene's\n"
                   "images as thumbnails (DIR/thumbs/) with its verdict, counts, device and times;\n"
                   "every verification's map is written too")
      ->type_name("DIR");
  command->add_option("--junit", a->junit, "also write the batch as JUnit XML (one testcase per scene) to FILE")
      ->type_name("FILE");
  return [a, backend] {
    a->backend_given = backend->count() > 0;
    return Render(*a);
  };
}

}  // namespace twinraster
