#include "bench/scale_bench.hpp"

#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
#include "bench/bench_suite.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "image/png_file.hpp"
#include "scene/scene_loader.hpp"

#include <nlohmann/json.hpp>
#include <sys/resource.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>

namespace twinraster {

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
  s << R"({"canvas": {"width": )" << width << R"(, "height": )" << height
    << R"(}, "viewport": {"width": )" << static_cast<double>(width) / height
    << R"(, "height": 1, "distance": 1}, "depth": {"near": 0.5, "far": )" << 4 * size << R"(},)"
    << R"("camera": {"eye": [)" << 0.9 * size << ", " << 0.7 * size << ", " << -1.6 * size
    << R"(], "center": [0, 0, 0], "up": [0, 1, 0]}, "models": {"cube": {"vertices": [[1, 1, 1], [-1, 1, 1], [-1, -1, 1], [1, -1, 1], [1, 1, -1], [-1, 1, -1], [-1, -1, -1], [1, -1, -1]], "triangles": [[0, 1, 2, "red"], [0, 2, 3, "red"], [4, 0, 3, "green"], [4, 3, 7, "green"], [5, 4, 7, "blue"], [5, 7, 6, "blue"], [1, 5, 6, "yellow"], [1, 6, 2, "yellow"], [4, 5, 1, "purple"], [4, 1, 0, "purple"], [2, 6, 7, "cyan"], [2, 7, 3, "cyan"]]}}, "instances": [)";
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

struct Stage {
  const char* key;
  const char* label;
  double ScaleRow::*value;
};
constexpr std::array<Stage, 8> kStages = {{
    {"load_ms", "load", &ScaleRow::load_ms},
    {"chain_ms", "host chain", &ScaleRow::chain_ms},
    {"gpu_setup_ms", "gpu set-up", &ScaleRow::gpu_setup_ms},
    {"gpu_draw_ms", "gpu draw", &ScaleRow::gpu_draw_ms},
    {"gpu_per_draw_ms", "gpu, F per draw", &ScaleRow::gpu_per_draw_ms},
    {"twin_setup_ms", "twin set-up", &ScaleRow::twin_setup_ms},
    {"twin_draw_ms", "twin draw", &ScaleRow::twin_draw_ms},
    {"png_ms", "png", &ScaleRow::png_ms},
}};

}  // namespace

ScaleResult RunScaleBench(const ScaleOptions& options) {
  if (options.counts.empty() || options.runs < 1) throw UsageError("bench --scale needs at least one count and one run");
  for (std::size_t count : options.counts) {
    if (count < 1 || count > kMaxInstances) throw UsageError("bench --scale: " + std::to_string(count) + " instances is outside 1.." + std::to_string(kMaxInstances));
  }
  std::vector<std::size_t> counts = options.counts;
  std::sort(counts.begin(), counts.end());  // increasing, so that the peak memory is this size's

  // Made once, as `render` with several scenes does: the path a user gets (instanced from
  // kInstancingThreshold draws of one mesh on), and F pushed per draw for comparison.
  GpuRenderer gpu;
  GpuRenderer pushing(GpuOptions{.device = "", .validation = false, .instancing = gpu::Instancing::kNever});
  ScaleResult result;
  result.machine = MachineDescription(gpu.DeviceName());
  result.runs = options.runs;
  for (std::size_t n = 0; n < counts.size(); ++n) {
    ScaleRow row;
    const std::string json = CubesJson(counts[n], options.width, options.height);
    row.json_bytes = json.size();
    std::vector<double> load, chain, gpu_setup, gpu_draw, gpu_per_draw, twin_setup, twin_draw, png;
    for (int run = 0; run < options.runs; ++run) {
      Stopwatch clock;
      const Scene scene = ParseScene(json, "cubes.json");
      load.push_back(clock.Lap());
      const DrawList list = BuildDrawList(scene);
      chain.push_back(clock.Lap());
      GpuTimings g;
      const Image gpu_image = gpu.Render(list, &g);
      gpu_setup.push_back(g.setup_ms);
      gpu_draw.push_back(g.draw_ms);
      GpuTimings p;
      const Image per_draw_image = pushing.Render(list, &p);
      gpu_per_draw.push_back(p.setup_ms + p.draw_ms);
      CpuTimings c;
      const Image twin_image = RenderOnCpu(list, {}, &c);
      twin_setup.push_back(c.setup_ms);
      twin_draw.push_back(c.draw_ms);
      clock.Lap();
      const std::string bytes = EncodePng(twin_image);
      png.push_back(clock.Lap());
      row.instances = list.draws.size();
      row.triangles = list.draws.size() * list.meshes.front().triangles.size();
      row.threads = c.threads;
      row.identical = CompareImages(gpu_image, twin_image).Equal() && CompareImages(per_draw_image, twin_image).Equal();
    }
    row.load_ms = Median(load), row.chain_ms = Median(chain), row.gpu_setup_ms = Median(gpu_setup);
    row.gpu_draw_ms = Median(gpu_draw), row.twin_setup_ms = Median(twin_setup), row.twin_draw_ms = Median(twin_draw);
    row.png_ms = Median(png);
    row.gpu_per_draw_ms = Median(gpu_per_draw);
    row.peak_mib = PeakMib();
    result.rows.push_back(row);
    if (options.on_row) options.on_row(row, n + 1, counts.size());
  }
  return result;
}

std::string ScaleTable(const ScaleResult& result) {
  std::ostringstream s;
  s << "Scale: cubes written out one instance each, medians of " << result.runs << " run(s); " << result.machine << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%10s %10s %9s |%8s %8s %9s %9s %9s %9s %9s %7s |%8s  %s\n", "instances", "triangles",
                "JSON MB", "load", "chain", "gpu setup", "gpu draw", "per-draw", "twin set", "twin draw", "png", "peak MB",
                "gpu == twin");
  s << line;
  for (const ScaleRow& r : result.rows) {
    std::snprintf(line, sizeof line, "%10zu %10zu %9.1f |%8.1f %8.1f %9.1f %9.1f %9.1f %9.1f %9.1f %7.1f |%8.0f  %s\n",
                  r.instances, r.triangles, static_cast<double>(r.json_bytes) / 1e6, r.load_ms, r.chain_ms, r.gpu_setup_ms,
                  r.gpu_draw_ms, r.gpu_per_draw_ms, r.twin_setup_ms, r.twin_draw_ms, r.png_ms, r.peak_mib,
                  r.identical ? "yes" : "NO");
    s << line;
  }
  s << "(milliseconds; per-draw: lavapipe's set-up + draw with F pushed per draw, against gpu set-up + draw as a user\n"
       " gets it, instanced from " << gpu::kInstancingThreshold << " draws of a mesh on; twin on " << (result.rows.empty() ? 0 : result.rows.front().threads)
    << " thread(s); peak MB: the process's peak resident memory after that size)\n";
  return s.str();
}

std::string ScaleCsv(const ScaleResult& result) {
  std::ostringstream s;
  s << "instances,triangles,json_bytes,threads";
  for (const Stage& stage : kStages) s << "," << stage.key;
  s << ",peak_mib,identical\n";
  for (const ScaleRow& r : result.rows) {
    s << r.instances << "," << r.triangles << "," << r.json_bytes << "," << r.threads;
    for (const Stage& stage : kStages) s << "," << r.*stage.value;
    s << "," << r.peak_mib << "," << (r.identical ? "true" : "false") << "\n";
  }
  return s.str();
}

nlohmann::ordered_json ScaleJson(const ScaleResult& result) {
  nlohmann::ordered_json j;
  j["format"] = kScaleJsonFormat;
  j["machine"] = result.machine;
  j["runs"] = result.runs;
  j["rows"] = nlohmann::ordered_json::array();
  for (const ScaleRow& r : result.rows) {
    nlohmann::ordered_json row;
    row["instances"] = r.instances;
    row["triangles"] = r.triangles;
    row["json_bytes"] = r.json_bytes;
    row["threads"] = r.threads;
    for (const Stage& stage : kStages) row[stage.key] = r.*stage.value;
    row["peak_mib"] = r.peak_mib;
    row["identical"] = r.identical;
    j["rows"].push_back(std::move(row));
  }
  return j;
}

std::string ScaleChartSvg(const ScaleResult& result) {
  constexpr double kWidth = 640, kHeight = 420, kLeft = 60, kRight = 150, kTop = 20, kBottom = 40;
  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (result.rows.empty()) return svg.str() + "</svg>\n";
  double x_lo = 1e300, x_hi = 0, y_lo = 1e300, y_hi = 0;
  for (const ScaleRow& r : result.rows) {
    x_lo = std::min(x_lo, static_cast<double>(r.instances)), x_hi = std::max(x_hi, static_cast<double>(r.instances));
    for (const Stage& stage : kStages) {
      const double v = std::max(r.*stage.value, 1e-3);
      y_lo = std::min(y_lo, v), y_hi = std::max(y_hi, v);
    }
  }
  const double lx0 = std::floor(std::log10(x_lo)), lx1 = std::max(lx0 + 1, std::ceil(std::log10(x_hi)));
  const double ly0 = std::floor(std::log10(y_lo)), ly1 = std::max(ly0 + 1, std::ceil(std::log10(y_hi)));
  const auto px = [&](double x) { return kLeft + (std::log10(x) - lx0) / (lx1 - lx0) * (kWidth - kLeft - kRight); };
  const auto py = [&](double y) { return kHeight - kBottom - (std::log10(std::max(y, 1e-3)) - ly0) / (ly1 - ly0) * (kHeight - kTop - kBottom); };
  for (double e = lx0; e <= lx1; ++e) {
    const double x = px(std::pow(10.0, e));
    svg << "<line x1=\"" << x << "\" y1=\"" << kTop << "\" x2=\"" << x << "\" y2=\"" << kHeight - kBottom
        << "\" stroke=\"#ddd\"/><text x=\"" << x << "\" y=\"" << kHeight - kBottom + 14 << "\" text-anchor=\"middle\">1e"
        << e << "</text>\n";
  }
  for (double e = ly0; e <= ly1; ++e) {
    const double y = py(std::pow(10.0, e));
    svg << "<line x1=\"" << kLeft << "\" y1=\"" << y << "\" x2=\"" << kWidth - kRight << "\" y2=\"" << y
        << "\" stroke=\"#ddd\"/><text x=\"" << kLeft - 6 << "\" y=\"" << y + 4 << "\" text-anchor=\"end\">1e" << e
        << "</text>\n";
  }
  svg << "<text x=\"" << (kLeft + kWidth - kRight) / 2 << "\" y=\"" << kHeight - 8
      << "\" text-anchor=\"middle\">instances (cubes, 12 triangles each)</text>\n"
      << "<text x=\"14\" y=\"" << (kTop + kHeight - kBottom) / 2 << "\" transform=\"rotate(-90 14 "
      << (kTop + kHeight - kBottom) / 2 << ")\" text-anchor=\"middle\">milliseconds (median)</text>\n";
  const char* colours[] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#7f7f7f", "#9467bd", "#8c564b", "#e377c2"};
  for (std::size_t k = 0; k < kStages.size(); ++k) {
    svg << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << colours[k] << "\" points=\"";
    for (const ScaleRow& r : result.rows) svg << px(static_cast<double>(r.instances)) << "," << py(r.*kStages[k].value) << " ";
    svg << "\"/>\n<text x=\"" << kWidth - kRight + 8 << "\" y=\"" << kTop + 14 + 16 * static_cast<double>(k) << "\" fill=\""
        << colours[k] << "\">" << kStages[k].label << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace twinraster
