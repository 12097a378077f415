#include "bench/scale_bench.hpp"

#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
#include "bench/bench_suite.hpp"
#include "chain/draw_list.hpp"
#include "files/png_file.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "run/backend_draws.hpp"
#include "run/judge_image.hpp"
#include "scene/scene_loader.hpp"
#include "twin_rules/lavapipe_path.hpp"
#include "twin_rules/twin_rules.hpp"

#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <sstream>

namespace twinraster::bench {

namespace {

// nx * ny * nz == count, the three as equal as the count's factors allow (1000 -> 10^3,
// 10000 -> 25 x 20 x 20).
std::array<std::size_t, 3> GridShape(std::size_t count) {
  std::array<std::size_t, 3> best{count, 1, 1};
  for (std::size_t x = 1; x * x * x <= count; ++x) {
    if (count % x != 0) continue;
    for (std::size_t y = x; x * y * y <= count; ++y) {
      if ((count / x) % y != 0) continue;
      const std::array<std::size_t, 3> shape{count / x / y, y, x};
      if (shape[0] - shape[2] < best[0] - best[2]) best = shape;
    }
  }
  return best;
}

// The chapter's cube, as in scenes/one-million-cubes.json, with every instance written out.
std::string CubesJson(std::size_t count, std::uint32_t width, std::uint32_t height) {
  const auto [nx, ny, nz] = GridShape(count);
  const double size = static_cast<double>(std::max({nx, ny, nz}));
  std::ostringstream s;
  s.precision(17);
  s << R"({"canvas": {"width": )" << width << R"(, "height": )" << height << R"(}, "viewport": {"width": )"
    << static_cast<double>(width) / height << R"(, "height": 1, "distance": 1}, "depth": {"near": 0.5, "far": )"
    << 4 * size << R"(},)"
    << R"("camera": {"eye": [)" << 0.9 * size << ", " << 0.7 * size << ", " << -1.6 * size
    << R"(], "center": [0, 0, 0], "up": [0, 1, 0]}, "models": {"cube": {"vertices": [)"
    << R"([1, 1, 1], [-1, 1, 1], [-1, -1, 1], [1, -1, 1], [1, 1, -1], [-1, 1, -1], [-1, -1, -1], [1, -1, -1]])"
    << R"(, "triangles": [[0, 1, 2, "red"], [0, 2, 3, "red"], [4, 0, 3, "green"], [4, 3, 7, "green"], )"
    << R"([5, 4, 7, "blue"], [5, 7, 6, "blue"], [1, 5, 6, "yellow"], [1, 6, 2, "yellow"], )"
    << R"([4, 5, 1, "purple"], [4, 1, 0, "purple"], [2, 6, 7, "cyan"], [2, 7, 3, "cyan"]]}}, "instances": [)";
  bool first = true;
  for (std::size_t k = 0; k < nz; ++k)
    for (std::size_t j = 0; j < ny; ++j)
      for (std::size_t i = 0; i < nx; ++i) {
        s << (first ? "" : ",\n") << R"({"model": "cube", "transform": {"scale": 0.3, "translation": [)"
          << static_cast<double>(i) - (static_cast<double>(nx) - 1) / 2 << ", "
          << static_cast<double>(j) - (static_cast<double>(ny) - 1) / 2 << ", "
          << static_cast<double>(k) - (static_cast<double>(nz) - 1) / 2 << "]}}";
        first = false;
      }
  s << "]}\n";
  return s.str();
}

double PeakMib() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace

ScaleResult RunScaleBench(const ScaleOptions& options) {
  if (options.counts.empty() || options.runs < 1)
    throw UsageError("bench --scale needs at least one count and one run");
  for (std::size_t count : options.counts) {
    if (count < 1 || count > kMaxInstances)
      throw UsageError("bench --scale: " + std::to_string(count) + " instances is outside 1.." +
                       std::to_string(kMaxInstances));
  }
  std::vector<std::size_t> counts = options.counts;
  std::sort(counts.begin(), counts.end());  // increasing, so that the peak memory is this size's

  // Made once, as `render` with several scenes does: the path a user gets (instanced from
  // kInstancingThreshold draws of one mesh on), and F pushed per draw for comparison.
  gpu::GpuRenderer gpu;
  gpu::GpuRenderer pushing(gpu::GpuOptions{.device = "", .validation = false, .instancing = gpu::Instancing::kNever});
  // The twin copies the lavapipe that draws here, as `render` chooses it.
  const cpu::RasterRules twin_rules =
      twin_rules::ChooseTwinRules(run::FactsOf(gpu.Device()), twin_rules::DetectCpuPath()).rules;
  ScaleResult result;
  result.machine = MachineDescription(gpu.DeviceName());
  result.runs = options.runs;
  result.width = options.width, result.height = options.height;
  if (options.processes) result.processes = RunProcessBench(*options.processes);
  for (std::size_t n = 0; n < counts.size(); ++n) {
    ScaleRow row;
    const std::string json = CubesJson(counts[n], options.width, options.height);
    row.json_bytes = json.size();
    std::vector<double> load, chain, gpu_setup, gpu_draw, gpu_per_draw, twin_setup, twin_draw, png, judge;
    Image frame;  // the twin's, for the PNG encoders
    for (int run = 0; run < options.runs; ++run) {
      Stopwatch clock;
      const Scene scene = ParseScene(json, "cubes.json");
      load.push_back(clock.Lap());
      const DrawList list = BuildDrawList(scene);
      chain.push_back(clock.Lap());
      gpu::GpuTimings g;
      const Image gpu_image = gpu.Render(list, &g);
      gpu_setup.push_back(g.setup_ms);
      gpu_draw.push_back(g.draw_ms);
      gpu::GpuTimings p;
      const Image per_draw_image = pushing.Render(list, &p);
      gpu_per_draw.push_back(p.setup_ms + p.draw_ms);
      const run::BackendRun twin = run::DrawOnTwin(list, twin_rules, 0);
      const Image& twin_image = twin.image;
      twin_setup.push_back(twin.record.setup_ms);
      twin_draw.push_back(twin.record.draw_ms);
      clock.Lap();
      const std::string bytes = files::EncodePng(twin_image);
      png.push_back(clock.Lap());
      frame = twin_image;
      judge.push_back(run::JudgeImage(scene, list, twin_image, twin.drawn_by.rasterizes, false).verify_ms);
      row.instances = list.draws.size();
      row.triangles = list.draws.size() * list.meshes.front().triangles.size();
      row.threads = twin.record.threads;
      row.identical = CompareImages(gpu_image, twin_image).Equal() && CompareImages(per_draw_image, twin_image).Equal();
    }
    row.load_ms = Median(load), row.chain_ms = Median(chain), row.gpu_setup_ms = Median(gpu_setup);
    row.gpu_draw_ms = Median(gpu_draw), row.twin_setup_ms = Median(twin_setup), row.twin_draw_ms = Median(twin_draw);
    row.png_ms = Median(png);
    row.gpu_per_draw_ms = Median(gpu_per_draw);
    row.verify_ms = Median(judge);
    row.peak_mib = PeakMib();
    row.png_encoders = ComparePngEncoders(frame, options.runs);
    result.rows.push_back(row);
    if (options.on_row) options.on_row(row, n + 1, counts.size());
  }
  return result;
}

}  // namespace twinraster::bench
