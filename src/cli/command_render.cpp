// `twinraster render SCENE`: draws the scene on lavapipe, on the CPU twin or both, writes the
// PNGs (staged: all or none) and compares the two images.
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "cli/comparison_report.hpp"
#include "cpu/cpu_renderer.hpp"
#include "chain/draw_list.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "image/png_file.hpp"
#include "scene/scene_loader.hpp"
#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"

#include <nlohmann/json.hpp>

#include <iostream>
#include <optional>
#include <sstream>
#include <thread>

namespace twinraster {

namespace {

struct BackendRun {
  std::string name;  // "gpu" or "cpu"
  std::string detail;  // device name, or thread count
  std::filesystem::path output;
  Image image;
  double setup_ms = 0, draw_ms = 0, readback_ms = 0, png_ms = 0;
};

// "out.png" -> "out-gpu.png"
std::filesystem::path Suffixed(const std::filesystem::path& out, const std::string& suffix) {
  std::filesystem::path p = out;
  const std::string extension = p.has_extension() ? p.extension().string() : ".png";
  p.replace_extension();
  p += "-" + suffix + extension;
  return p;
}

BackendRun RenderGpu(const DrawList& list, const std::string& device) {
  BackendRun run{"gpu", "", {}, {}};
  Stopwatch clock;
  GpuRenderer renderer(GpuOptions{device, false});
  const double device_ms = clock.Milliseconds();
  run.detail = renderer.DeviceName();
  GpuTimings t;
  run.image = renderer.Render(list, &t);
  // Set-up is everything before the draw: instance, device and pipeline, then buffers.
  run.setup_ms = device_ms + t.setup_ms, run.draw_ms = t.draw_ms, run.readback_ms = t.readback_ms;
  return run;
}

BackendRun RenderCpu(const DrawList& list, unsigned threads) {
  BackendRun run{"cpu", "", {}, {}};
  CpuTimings t;
  run.image = RenderOnCpu(list, CpuOptions{threads}, &t);
  run.detail = "CPU twin, " + std::to_string(t.threads) + (t.threads == 1 ? " thread" : " threads");
  run.setup_ms = t.setup_ms, run.draw_ms = t.draw_ms, run.readback_ms = t.readback_ms;
  return run;
}

nlohmann::ordered_json RunJson(const BackendRun& run) {
  return {{"output", run.output.string()},
          {"device", run.detail},
          {"timings_ms",
           {{"setup", run.setup_ms}, {"draw", run.draw_ms}, {"readback", run.readback_ms}, {"png", run.png_ms}}}};
}

std::string RunText(const BackendRun& run) {
  std::ostringstream s;
  s.precision(3);
  s << std::fixed << run.name << ": " << run.output.string() << "  (" << run.detail << ")  setup " << run.setup_ms
    << " ms, draw " << run.draw_ms << " ms, readback " << run.readback_ms << " ms, png " << run.png_ms << " ms";
  return s.str();
}

}  // namespace

int RenderCommand(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--json"}, {"-o", "--backend", "--device", "--threads"});
  cl.ExpectPositional({"SCENE"});
  const std::string backend = cl.Option("--backend").value_or("both");
  if (backend != "gpu" && backend != "cpu" && backend != "both") {
    throw UsageError("--backend must be gpu, cpu or both, not \"" + backend + "\"");
  }
  const unsigned threads = static_cast<unsigned>(cl.Index("--threads").value_or(0));
  const std::filesystem::path scene_file = cl.Positional()[0];
  const Scene scene = LoadScene(scene_file);
  const std::filesystem::path out = cl.Option("-o").value_or(scene.name + ".png");
  std::error_code ignored;
  if (out.filename().empty() || std::filesystem::is_directory(out, ignored)) {
    throw UsageError("-o " + out.string() + ": give a file name (OUT.png), not a directory");
  }
  const DrawList list = BuildDrawList(scene);

  // Render everything before writing anything: a run that fails writes no file at all.
  std::vector<BackendRun> runs;
  if (backend != "cpu") {
    runs.push_back(RenderGpu(list, cl.Option("--device").value_or("")));  // GpuUnavailable: exit 3
  }
  if (backend != "gpu") runs.push_back(RenderCpu(list, threads));
  for (BackendRun& run : runs) run.output = backend == "both" ? Suffixed(out, run.name) : out;

  std::optional<Comparison> comparison;
  const std::filesystem::path diff_file = Suffixed(out, "diff");
  if (runs.size() == 2) comparison = CompareImages(runs[0].image, runs[1].image);

  // Every output is staged in full before any is renamed into place.
  std::vector<StagedFile> staged;
  for (BackendRun& run : runs) {
    Stopwatch clock;
    staged.push_back(StagePng(run.output, run.image));
    run.png_ms = clock.Milliseconds();
  }
  const bool wrote_diff = comparison && !comparison->Equal();
  if (wrote_diff) staged.push_back(StagePng(diff_file, DiffImage(runs[0].image, runs[1].image)));
  for (StagedFile& file : staged) file.Commit();
  // A diff left by an earlier run would now describe images that no longer exist.
  if (comparison && comparison->Equal() && std::filesystem::is_regular_file(diff_file, ignored)) {
    std::filesystem::remove(diff_file, ignored);
  }

  if (cl.Flag("--json")) {
    nlohmann::ordered_json j;
    j["scene"] = scene_file.string();
    j["width"] = list.width;
    j["height"] = list.height;
    j["differing_pixels"] = comparison ? nlohmann::ordered_json(comparison->differing_pixels) : nullptr;
    j["max_channel_difference"] = comparison ? nlohmann::ordered_json(comparison->max_channel_difference) : nullptr;
    j["diff"] = wrote_diff ? nlohmann::ordered_json(diff_file.string()) : nullptr;
    for (const BackendRun& run : runs) j["backends"][run.name] = RunJson(run);
    std::cout << j.dump(2) << "\n";
  } else {
    for (const BackendRun& run : runs) std::cout << RunText(run) << "\n";
    if (comparison) {
      std::cout << "gpu vs cpu: " << ComparisonText(runs[0].image, runs[1].image, *comparison)
                << (wrote_diff ? ", diff in " + diff_file.string() : "") << "\n";
    }
  }
  return comparison && !comparison->Equal() ? kExitImagesDiffer : kExitOk;
}

}  // namespace twinraster
