// `twinraster render SCENE`: draws the scene on lavapipe, on the CPU twin or both, writes the
// PNGs (staged: all or none, or one PNG to standard output) and compares the two images.
#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
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

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>
#include <optional>
#include <sstream>

namespace twinraster {

namespace {

struct RenderArguments {
  std::string scene;
  std::optional<std::string> output;
  std::string backend = "both";
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

BackendRun RenderGpu(const DrawList& list, const std::string& device, Progress& progress) {
  BackendRun run{"gpu", "", {}, {}};
  progress.Status("gpu: starting Vulkan...");
  Stopwatch clock;
  GpuOptions options;
  options.device = device;
  GpuRenderer renderer(options);
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

// Every check on the arguments that needs no scene and no device, so that a mistake costs nothing.
void CheckOutput(const RenderArguments& a) {
  if (IsStandardStream(a.scene) && !a.output) {
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

int Render(const RenderArguments& a) {
  CheckOutput(a);
  Progress progress = Progress::OnStandardError(a.quiet);
  progress.Status("reading the scene...");
  const Scene scene = LoadSceneArgument(a.scene);
  const std::string out = a.output.value_or(scene.name + ".png");
  const bool to_stdout = IsStandardStream(out);
  const DrawList list = BuildDrawList(scene);

  // Render everything before writing anything: a run that fails writes no file at all.
  std::vector<BackendRun> runs;
  if (a.backend != "cpu") runs.push_back(RenderGpu(list, a.device, progress));  // GpuUnavailable: exit 3
  if (a.backend != "gpu") runs.push_back(RenderCpu(list, a.threads, progress));
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
    if (to_stdout) png_bytes = EncodePng(run.image);
    else staged.push_back(StagePng(run.output, run.image));
    run.png_ms = clock.Milliseconds();
  }
  const bool wrote_diff = comparison && !comparison->Equal();
  if (wrote_diff) staged.push_back(StagePng(diff_file, DiffImage(runs[0].image, runs[1].image)));
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
    j["scene"] = a.scene;
    j["width"] = list.width;
    j["height"] = list.height;
    j["differing_pixels"] = comparison ? Json(comparison->differing_pixels) : Json(nullptr);
    j["max_channel_difference"] = comparison ? Json(comparison->max_channel_difference) : Json(nullptr);
    j["diff"] = wrote_diff ? Json(diff_file) : Json(nullptr);
    j["backends"] = {{"gpu", RunJson(find_run("gpu"))}, {"cpu", RunJson(find_run("cpu"))}};
    std::cout << j.dump(2) << "\n";
  } else if (!(to_stdout && a.quiet)) {
    // With -o - standard output carries the PNG alone, so the report goes to standard error.
    std::ostream& report = to_stdout ? std::cerr : std::cout;
    for (const BackendRun& run : runs) report << RunText(run) << "\n";
    if (comparison) {
      report << "gpu vs cpu: " << ComparisonText(runs[0].image, runs[1].image, *comparison)
             << (wrote_diff ? ", diff in " + diff_file : "") << "\n";
    }
  }
  return comparison && !comparison->Equal() ? kExitImagesDiffer : kExitOk;
}

}  // namespace

CommandRun AddRenderCommand(CLI::App& app) {
  auto a = std::make_shared<RenderArguments>();
  CLI::App* command = AddSubcommand(
      app, "render", "draw a scene on Vulkan, on the CPU twin, or on both and compare",
      "Each PNG is written whole to a temporary file and renamed into place: a failed run leaves\n"
      "earlier files untouched. On a terminal, progress shows on standard error.\n"
      "Exit codes: 0 done (both: identical images), 1 the images differ, 2 bad input or usage,\n"
      "3 no usable Vulkan device (--backend cpu needs none), 4 internal error.");
  command->add_option("SCENE", a->scene, "the scene file (JSON), or - to read it from standard input")->required();
  command
      ->add_option("-o,--output", a->output,
                   "gpu, cpu: write OUT.png; both: OUT-gpu.png, OUT-cpu.png and, when\n"
                   "they differ, OUT-diff.png. Default: the scene's name in the current\n"
                   "directory. - writes the PNG to standard output (gpu or cpu only)")
      ->type_name("OUT.png");
  ExpectOneOf(command->add_option("--backend", a->backend, "where to draw (default: both)")->type_name("gpu|cpu|both"),
              "backend", {"gpu", "cpu", "both"});
  command->add_flag("--json", a->json, "print the report as JSON (twinraster.render/1, docs/json-output.md)");
  command->add_option("--device", a->device, "the Vulkan device whose name contains NAME (default: lavapipe)")
      ->type_name("NAME");
  ExpectIndex(command->add_option("--threads", a->threads, "the CPU twin's threads (default: all cores)")->type_name("N"));
  command->add_flag("-q,--quiet", a->quiet, "no progress on standard error (and, with -o -, no report)");
  return [a] { return Render(*a); };
}

}  // namespace twinraster
