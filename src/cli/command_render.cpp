// `twinraster render SCENE...`: draws each scene on lavapipe, on the CPU twin or both, or (--rules
// book) as the chapter's demos draw it; writes the PNGs (staged: all of a scene's or none, or one
// PNG to standard output) and compares the images. Several scenes share one Vulkan device and
// pipeline, and write into one directory.
#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
#include "book/book_renderer.hpp"
#include "chain/draw_list.hpp"
#include "cli/commands.hpp"
#include "cli/comparison_report.hpp"
#include "cli/io_arguments.hpp"
#include "cli/parser_setup.hpp"
#include "cli/progress.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "image/png_file.hpp"
#include "scene/scene_error.hpp"

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
  bool json = false;
  std::string device;
  unsigned threads = 0;
  bool quiet = false;
};

struct BackendRun {
  std::string name;    // "gpu" or "cpu"
  std::string detail;  // device name, or thread count
  std::string output;  // a file, or "-" for standard output
  Image image;
  double setup_ms = 0, draw_ms = 0, readback_ms = 0, png_ms = 0;
};

// "out.png" -> "out-gpu.png"
std::string Suffixed(const std::string& out, const std::string& suffix) {
  std::filesystem::path p = out;
  const std::string extension = p.extension().string();
  p.replace_extension();
  p += "-" + suffix + extension;
  return p.string();
}

// The Vulkan device and pipeline are made for the first scene and kept for the others, so that
// its set-up time includes them and later scenes' do not.
BackendRun RenderGpu(const DrawList& list, const std::string& device, std::optional<GpuRenderer>& gpu,
                     Progress& progress) {
  BackendRun run{"gpu", "", {}, {}};
  Stopwatch clock;
  if (!gpu) {
    progress.Status("gpu: starting Vulkan...");
    GpuOptions options;
    options.device = device;
    gpu.emplace(options);
  }
  GpuRenderer& renderer = *gpu;
  const double device_ms = clock.Milliseconds();
  run.detail = renderer.DeviceName();
  progress.Status("gpu: drawing on " + run.detail + "...");
  GpuTimings t;
  run.image = renderer.Render(list, &t);
  // Set-up is everything before the draw: instance, device and pipeline, then buffers.
  run.setup_ms = device_ms + t.setup_ms, run.draw_ms = t.draw_ms, run.readback_ms = t.readback_ms;
  return run;
}

BackendRun RenderCpu(const DrawList& list, unsigned threads, Progress& progress) {
  BackendRun run{"cpu", "", {}, {}};
  progress.Status("cpu: drawing...");
  CpuOptions options;
  options.threads = threads;
  CpuTimings t;
  run.image = RenderOnCpu(list, options, &t);
  run.detail = "CPU twin, " + std::to_string(t.threads) + (t.threads == 1 ? " thread" : " threads");
  run.setup_ms = t.setup_ms, run.draw_ms = t.draw_ms, run.readback_ms = t.readback_ms;
  return run;
}

// The chapter's demos draw on one thread, straight into the image: all of it is drawing.
BackendRun RenderBook(const Scene& scene, const std::string& scene_argument, Progress& progress) {
  BackendRun run{"cpu", "book rules: the chapter's demos, 1 thread", {}, {}};
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

nlohmann::ordered_json RunJson(const BackendRun* run) {
  if (!run) return nullptr;  // the backend was not asked for
  return {{"output", run->output},
          {"device", run->detail},
          {"timings_ms",
           {{"setup", run->setup_ms}, {"draw", run->draw_ms}, {"readback", run->readback_ms}, {"png", run->png_ms}}}};
}

std::string RunText(const BackendRun& run) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << run.name << ": " << (IsStandardStream(run.output) ? "standard output" : run.output) << "  ("
    << run.detail << ")  setup " << run.setup_ms << " ms, draw " << run.draw_ms << " ms, readback " << run.readback_ms
    << " ms, png " << run.png_ms << " ms";
  return s.str();
}

// --rules book draws on the CPU only, so it implies --backend cpu; asking for another is a mistake.
void ResolveRules(RenderArguments& a) {
  if (a.rules != "book") return;
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
  if (StandardOutputIsTerminal()) {
    throw UsageError("-o -: standard output is a terminal; redirect it (> out.png) or pipe it to another program");
  }
}

// One scene, from reading it to its report. `directory`: where several scenes' files go.
int RenderScene(const RenderArguments& a, const std::string& scene_argument, const std::optional<std::string>& directory,
                std::optional<GpuRenderer>& gpu, Progress& progress) {
  progress.Status("reading " + scene_argument + "...");
  Stopwatch load_clock;
  Scene scene = LoadSceneArgument(scene_argument);
  if (a.wireframe) scene.wireframe = true;
  const std::string out = directory ? (std::filesystem::path(*directory) / (scene.name + ".png")).string()
                                    : a.output.value_or(scene.name + ".png");
  const bool to_stdout = IsStandardStream(out);
  const bool book = a.rules == "book";
  const DrawList list = book ? DrawList{} : BuildDrawList(scene);  // the book draws from the scene
  const double load_ms = load_clock.Milliseconds();
  std::size_t triangles = 0;
  for (const Instance& instance : scene.instances) triangles += scene.models[instance.model].triangles.size();

  // Render everything before writing anything: a run that fails writes no file at all.
  std::vector<BackendRun> runs;
  if (book) {
    runs.push_back(RenderBook(scene, scene_argument, progress));
  } else {
    if (a.backend != "cpu") runs.push_back(RenderGpu(list, a.device, gpu, progress));  // GpuUnavailable: exit 3
    if (a.backend != "gpu") runs.push_back(RenderCpu(list, a.threads, progress));
  }
  for (BackendRun& run : runs) run.output = a.backend == "both" ? Suffixed(out, run.name) : out;

  std::optional<Comparison> comparison;
  const std::string diff_file = to_stdout ? "" : Suffixed(out, "diff");
  if (runs.size() == 2) {
    progress.Status("comparing gpu and cpu...");
    comparison = CompareImages(runs[0].image, runs[1].image);
  }

  // Every output is encoded and staged in full before any is renamed into place (or written out).
  progress.Status(runs.size() == 1 ? "writing the PNG..." : "writing the PNGs...");
  std::vector<StagedFile> staged;
  std::string png_bytes;  // for -o -
  for (BackendRun& run : runs) {
    Stopwatch clock;
    if (to_stdout) png_bytes = EncodePng(run.image, a.png_level);
    else staged.push_back(StagePng(run.output, run.image, a.png_level));
    run.png_ms = clock.Milliseconds();
  }
  const bool wrote_diff = comparison && !comparison->Equal();
  if (wrote_diff) staged.push_back(StagePng(diff_file, DiffImage(runs[0].image, runs[1].image), a.png_level));
  for (StagedFile& file : staged) file.Commit();
  // A diff left by an earlier run would now describe images that no longer exist.
  std::error_code ignored;
  if (comparison && comparison->Equal() && std::filesystem::is_regular_file(diff_file, ignored)) {
    std::filesystem::remove(diff_file, ignored);
  }
  progress.Clear();
  if (to_stdout) WriteStandardOutput(png_bytes);

  const auto find_run = [&](const char* name) -> const BackendRun* {
    for (const BackendRun& run : runs)
      if (run.name == name) return &run;
    return nullptr;
  };
  if (a.json) {
    using Json = nlohmann::ordered_json;
    Json j;
    j["format"] = kRenderJsonFormat;
    j["scene"] = scene_argument;
    j["rules"] = a.rules;
    j["wireframe"] = a.rules == "book" || scene.wireframe;  // the book's demos draw wireframes only
    j["width"] = scene.canvas.width;
    j["height"] = scene.canvas.height;
    j["instances"] = scene.instances.size();
    j["triangles"] = triangles;
    j["load_ms"] = load_ms;
    j["differing_pixels"] = comparison ? Json(comparison->differing_pixels) : Json(nullptr);
    j["max_channel_difference"] = comparison ? Json(comparison->max_channel_difference) : Json(nullptr);
    j["diff"] = wrote_diff ? Json(diff_file) : Json(nullptr);
    j["backends"] = {{"gpu", RunJson(find_run("gpu"))}, {"cpu", RunJson(find_run("cpu"))}};
    // One scene: the object, indented. Several: JSON Lines, one object per scene as it finishes.
    std::cout << (directory ? j.dump() : j.dump(2)) << "\n" << std::flush;
  } else if (!(to_stdout && a.quiet)) {
    // With -o - standard output carries the PNG alone, so the report goes to standard error.
    std::ostream& report = to_stdout ? std::cerr : std::cout;
    std::ostringstream work;
    work.precision(3);
    const std::size_t instances = scene.instances.size();
    work << std::fixed << scene_argument << ": " << instances << (instances == 1 ? " instance, " : " instances, ") << triangles
         << " triangles, " << scene.canvas.width << " x " << scene.canvas.height << ", loaded in " << load_ms << " ms";
    report << work.str() << "\n";
    for (const BackendRun& run : runs) report << RunText(run) << "\n";
    if (comparison) {
      report << "gpu vs cpu: " << ComparisonText(runs[0].image, runs[1].image, *comparison)
             << (wrote_diff ? ", diff in " + diff_file : "") << "\n";
    }
  }
  return comparison && !comparison->Equal() ? kExitImagesDiffer : kExitOk;
}

int Render(RenderArguments& a) {
  ResolveRules(a);
  CheckOutput(a);
  Progress progress = Progress::OnStandardError(a.quiet);
  std::optional<GpuRenderer> gpu;
  if (a.scenes.size() == 1) return RenderScene(a, a.scenes.front(), std::nullopt, gpu, progress);

  const std::string directory = a.output.value_or(".");
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw FileError(directory + ": cannot create the directory: " + error.message());
  // Each scene on its own: a bad scene or an unwritable output is reported and the others still
  // render; the exit code is the worst of them. No Vulkan device ends the run (exit 3).
  int worst = kExitOk;
  for (const std::string& scene : a.scenes) {
    int code = kExitOk;
    try {
      code = RenderScene(a, scene, directory, gpu, progress);
    } catch (const SceneError& e) {
      progress.Clear();
      std::cerr << "twinraster: " << e.what() << "\n";
      code = kExitBadInput;
    } catch (const FileError& e) {
      progress.Clear();
      std::cerr << "twinraster: " << e.what() << "\n";
      code = kExitBadInput;
    }
    worst = std::max(worst, code);
  }
  return worst;
}

}  // namespace

CommandRun AddRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* command = AddSubcommand(
      app, "render", "draw a scene on Vulkan, on the CPU twin, or on both and compare; or as the book's demos do",
      "Each PNG is written whole to a temporary file and renamed into place: a failed run leaves\n"
      "earlier files untouched. On a terminal, progress shows on standard error.\n"
      "Exit codes: 0 done (both: identical images), 1 the images differ, 2 bad input or usage,\n"
      "3 no usable Vulkan device (--backend cpu needs none), 4 internal error.");
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
  command->add_flag("--json", a->json, "print the report as JSON (twinraster.render/1, docs/json-output.md)");
  command->add_option("--device", a->device, "the Vulkan device whose name contains NAME (default: lavapipe)")
      ->type_name("NAME");
  ExpectIndex(command->add_option("--threads", a->threads, "the CPU twin's threads (default: all cores)")->type_name("N"));
  command->add_flag("-q,--quiet", a->quiet, "no progress on standard error (and, with -o -, no report)");
  return [a, backend] {
    a->backend_given = backend->count() > 0;
    return Render(*a);
  };
}

}  // namespace twinraster
