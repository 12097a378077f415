#include "bench_report/bench_tables.hpp"

#include "base/counted.hpp"
#include "bench/vertex_methods.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <sstream>
#include <utility>

namespace twinraster::bench_report {

namespace {

std::string Fixed(double x, int decimals) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.*f", decimals, x);
  return buffer;
}

std::string Sci(double x) {
  if (x < 0) return "-";
  if (x == 0) return "0";
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.2e", x);
  return buffer;
}

const bench::BenchRow* Find(const bench::BenchResult& result, const std::string& scene, const std::string& method,
                            unsigned threads = 0) {
  for (const bench::BenchRow& r : result.rows)
    if (r.scene == scene && r.method == method && (threads == 0 || r.threads == threads)) return &r;
  return nullptr;
}

struct ZFightOnset {
  std::optional<double> ratio;           // the largest near/far ratio that z-fights; none: no ratio tried does
  std::optional<double> smallest_tried;  // none: no depth-ratio scene ran, so nothing was measured
};

// From the depth-ratio scenes' CPU twin rows ("hard/depth-ratio-1e-4" is near/far = 1e-4).
ZFightOnset Onset(const bench::BenchResult& result, bool reversed) {
  ZFightOnset onset;
  for (const bench::BenchRow& r : result.rows) {
    const std::size_t at = r.scene.find("depth-ratio-1e-");
    if (at == std::string::npos || r.method != "cpu-twin" || !r.z_fighting_px) continue;
    if ((r.scene.find("reversed") != std::string::npos) != reversed) continue;
    const double ratio = std::pow(10.0, -std::atof(r.scene.c_str() + at + 15));
    onset.smallest_tried = std::min(onset.smallest_tried.value_or(ratio), ratio);
    if (*r.z_fighting_px > 0 && (!onset.ratio || ratio > *onset.ratio)) onset.ratio = ratio;
  }
  return onset;
}

// A summary section: its heading, then its lines; nothing at all when it has no line, so that a run
// of a few scenes shows no heading for the scenes it left out.
void PutSection(std::ostream& out, const std::string& heading, const std::string& lines) {
  if (!lines.empty()) out << heading << "\n" << lines;
}

// The scene with the most vertices gives the steadiest per-vertex cost.
const bench::BenchRow* Largest(const bench::BenchResult& result) {
  const bench::BenchRow* largest = nullptr;
  for (const bench::BenchRow& r : result.rows)
    if (!largest || r.vertices > largest->vertices) largest = &r;
  return largest;
}

std::vector<std::string> Scenes(const bench::BenchResult& result) {
  std::vector<std::string> scenes;
  for (const bench::BenchRow& r : result.rows)
    if (std::find(scenes.begin(), scenes.end(), r.scene) == scenes.end()) scenes.push_back(r.scene);
  return scenes;
}

// The thread counts `device`'s rows were measured with.
std::vector<unsigned> ThreadCounts(const bench::BenchResult& result, std::string_view device) {
  std::vector<unsigned> counts;
  for (const bench::BenchRow& r : result.rows)
    if (r.method == device && std::find(counts.begin(), counts.end(), r.threads) == counts.end())
      counts.push_back(r.threads);
  return counts;
}

// A device and the twin with its rules, whose whole-frame times the summary divides.
struct DevicePair {
  const char* key;     // the JSON key's suffix, and the device's method
  const char* device;  // BenchRow::method
  const char* twin;
  const char* title;
};
constexpr DevicePair kDevicePairs[] = {
    {"lavapipe", "lavapipe", "cpu-twin", "CPU twin time / lavapipe time"},
    {"swiftshader", "swiftshader", "cpu-twin-swiftshader",
     "CPU twin with SwiftShader's rules / SwiftShader (its own pool, every core)"},
};

}  // namespace

nlohmann::ordered_json BenchSummaryJson(const bench::BenchResult& result) {
  using Json = nlohmann::ordered_json;
  const auto number_or_null = [](std::optional<double> x) { return x ? Json(*x) : Json(nullptr); };
  // Every key is present whatever was run (docs/json-output.md): null stands for "not measured".
  Json j;
  Json& far = j["far_1e7_vertex_error_px"] = Json::object();
  for (bench::VertexMethod m : bench::kAllMethods) {
    const std::string method(bench::MethodName(m));
    const bench::BenchRow* r = Find(result, "hard/far-1e7", method);
    far[method] = number_or_null(r && r->vertex_error_px >= 0 ? std::optional(r->vertex_error_px) : std::nullopt);
  }
  for (const bool reversed : {false, true}) {
    j["z_fighting_onset_near_over_far"][reversed ? "reversed" : "standard"] =
        number_or_null(Onset(result, reversed).ratio);
  }
  const bench::BenchRow* largest = Largest(result);
  Json& per_million = j["vertex_ms_per_million_vertices"] = Json::object();
  per_million["scene"] = largest ? Json(largest->scene) : Json(nullptr);
  for (bench::VertexMethod m : bench::kAllMethods) {
    const std::string method(bench::MethodName(m));
    const bench::BenchRow* r = largest ? Find(result, largest->scene, method) : nullptr;
    per_million[method] = number_or_null(r && r->vertex_ms >= 0 && r->vertices > 0
                                             ? std::optional(r->vertex_ms * 1e6 / double(r->vertices))
                                             : std::nullopt);
  }
  // Lists rather than objects keyed by scene and thread count, so that their keys never vary.
  for (const DevicePair& pair : kDevicePairs) {
    Json& ratios = j[std::string("cpu_twin_over_") + pair.key] = Json::array();
    for (const std::string& scene : Scenes(result)) {
      for (unsigned threads : ThreadCounts(result, pair.device)) {
        const bench::BenchRow* twin = Find(result, scene, pair.twin, threads);
        const bench::BenchRow* gpu = Find(result, scene, pair.device, threads);
        if (!twin || !gpu) continue;
        ratios.push_back({{"scene", scene},
                          {"threads", threads},
                          {"cpu_twin_ms", twin->frame_ms},
                          {std::string(pair.key) + "_ms", gpu->frame_ms},
                          {"ratio", twin->frame_ms / gpu->frame_ms}});
      }
    }
  }
  return j;
}

std::string BenchSummary(const bench::BenchResult& result) {
  std::ostringstream out, lines;
  for (bench::VertexMethod m : bench::kAllMethods) {
    const std::string method(bench::MethodName(m));
    if (const bench::BenchRow* r = Find(result, "hard/far-1e7", method))
      lines << "  " << method << ": " << Sci(r->vertex_error_px) << " px"
            << (r->vertex_error_px < 1.0 / 256 ? "  (under 1/256 px)" : "") << "\n";
  }
  PutSection(out, "Vertex error at 1e7 units from the origin (hard/far-1e7, 1920x1080), max over vertices:",
             std::exchange(lines, {}).str());
  for (const bool reversed : {false, true}) {
    const ZFightOnset onset = Onset(result, reversed);
    if (!onset.smallest_tried) continue;  // "none" is a result only where a depth-ratio scene ran
    lines << "  " << (reversed ? "reversed Z: " : "standard Z: ")
          << (onset.ratio ? "near/far = " + Sci(*onset.ratio) : "none down to near/far = " + Sci(*onset.smallest_tried))
          << "\n";
  }
  PutSection(out, "Z-fighting onset (D32_SFLOAT, plates 0.02 apart at ~45 units; largest near/far that fights):",
             std::exchange(lines, {}).str());
  if (const bench::BenchRow* largest = Largest(result)) {
    for (bench::VertexMethod m : bench::kAllMethods) {
      const std::string method(bench::MethodName(m));
      if (const bench::BenchRow* r = Find(result, largest->scene, method))
        lines << "  " << method << ": " << Fixed(r->vertex_ms * 1e6 / double(r->vertices), 2) << "\n";
    }
    PutSection(out,
               "Vertex stage, ms per million vertices (" + largest->scene + ", " +
                   Counted(largest->vertices, "vertex", "vertices") + "):",
               std::exchange(lines, {}).str());
  }
  for (const DevicePair& pair : kDevicePairs) {
    const std::vector<unsigned> counts = ThreadCounts(result, pair.device);
    if (counts.empty()) continue;
    out << "Whole frame, " << pair.title << ":\n";
    char line[256];
    std::snprintf(line, sizeof line, "  %-44s", "scene");
    out << line;
    for (unsigned t : counts) out << "  " << t << (t == 1 ? " thread " : " threads");
    out << "\n";
    for (const std::string& scene : Scenes(result)) {
      std::snprintf(line, sizeof line, "  %-44s", scene.c_str());
      out << line;
      for (unsigned threads : counts) {
        const bench::BenchRow* twin = Find(result, scene, pair.twin, threads);
        const bench::BenchRow* gpu = Find(result, scene, pair.device, threads);
        std::snprintf(line, sizeof line, "  %9s", twin && gpu ? Fixed(twin->frame_ms / gpu->frame_ms, 3).c_str() : "-");
        out << line;
      }
      out << "\n";
    }
  }
  return out.str();
}

std::string BenchTable(const bench::BenchResult& result) {
  std::ostringstream out;
  char line[512];
  std::snprintf(line, sizeof line, "%-44s %-20s %3s %10s %10s %12s %10s %9s %19s\n", "scene", "method", "thr",
                "vertex ms", "frame ms", "vertex err px", "image err", "z-fight", "colour err (pixels)");
  out << line;
  for (const bench::BenchRow& r : result.rows) {
    const std::string colour =
        r.colour_error ? std::to_string(*r.colour_error) + " (" + std::to_string(r.colour_pixels) + ")" : "-";
    std::snprintf(line, sizeof line, "%-44s %-20s %3u %10s %10s %12s %10llu %9s %19s\n", r.scene.c_str(),
                  r.method.c_str(), r.threads, r.vertex_ms < 0 ? "-" : Fixed(r.vertex_ms, 3).c_str(),
                  Fixed(r.frame_ms, 2).c_str(), Sci(r.vertex_error_px).c_str(),
                  static_cast<unsigned long long>(r.image_error_px),
                  r.z_fighting_px ? std::to_string(*r.z_fighting_px).c_str() : "-", colour.c_str());
    out << line;
  }
  out << "colour err: lit scenes only, the largest channel difference (0-255) from the truth's colours, over the\n"
         "pixels where the method shows the same triangle as the truth (how many in brackets)\n";
  out << "medians of " << Counted(result.runs, "run") << "; " << result.machine << "; " << Fixed(result.seconds, 1)
      << " s\n\n";
  out << BenchSummary(result);
  return out.str();
}

std::string BenchCsv(const bench::BenchResult& result) {
  std::ostringstream out;
  out << "scene,method,threads,width,height,vertices,triangles,vertex_ms,frame_ms,vertex_error_px,image_error_px,"
         "z_fighting_px,colour_error,colour_pixels\n";
  out.precision(9);
  for (const bench::BenchRow& r : result.rows) {
    out << r.scene << ',' << r.method << ',' << r.threads << ',' << r.width << ',' << r.height << ',' << r.vertices
        << ',' << r.triangles << ',' << (r.vertex_ms < 0 ? std::string() : std::to_string(r.vertex_ms)) << ','
        << r.frame_ms << ',' << (r.vertex_error_px < 0 ? std::string() : Sci(r.vertex_error_px)) << ','
        << r.image_error_px << ',' << (r.z_fighting_px ? std::to_string(*r.z_fighting_px) : std::string()) << ','
        << (r.colour_error ? std::to_string(*r.colour_error) : std::string()) << ','
        << (r.colour_error ? std::to_string(r.colour_pixels) : std::string()) << '\n';
  }
  return out.str();
}

nlohmann::ordered_json BenchJson(const bench::BenchResult& result) {
  nlohmann::ordered_json j;
  j["format"] = kBenchJsonFormat;
  j["machine"] = result.machine;
  j["runs"] = result.runs;
  j["seconds"] = result.seconds;
  j["summary"] = BenchSummaryJson(result);
  j["rows"] = nlohmann::ordered_json::array();
  for (const bench::BenchRow& r : result.rows) {
    nlohmann::ordered_json row = {
        {"scene", r.scene},         {"method", r.method},     {"threads", r.threads},
        {"width", r.width},         {"height", r.height},     {"vertices", r.vertices},
        {"triangles", r.triangles}, {"frame_ms", r.frame_ms}, {"image_error_px", r.image_error_px}};
    row["vertex_ms"] = r.vertex_ms < 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.vertex_ms);
    row["vertex_error_px"] =
        r.vertex_error_px < 0 ? nlohmann::ordered_json(nullptr) : nlohmann::ordered_json(r.vertex_error_px);
    row["z_fighting_px"] = r.z_fighting_px ? nlohmann::ordered_json(*r.z_fighting_px) : nlohmann::ordered_json(nullptr);
    row["colour_error"] = r.colour_error ? nlohmann::ordered_json(*r.colour_error) : nlohmann::ordered_json(nullptr);
    row["colour_pixels"] = r.colour_error ? nlohmann::ordered_json(r.colour_pixels) : nlohmann::ordered_json(nullptr);
    j["rows"].push_back(row);
  }
  return j;
}

std::string BenchProgressLine(const bench::BenchRow& row, std::size_t done, std::size_t total) {
  const std::string count = std::to_string(total);
  std::string number = std::to_string(done);
  number.insert(0, count.size() > number.size() ? count.size() - number.size() : 0, ' ');  // rows line up
  std::string line =
      "[" + number + "/" + count + "] " + row.scene + " " + row.method + ", " + Counted(row.threads, "thread") + ": ";
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "frame %.2f ms", row.frame_ms);
  line += numbers;
  if (row.vertex_error_px >= 0) {
    std::snprintf(numbers, sizeof numbers, ", vertex error %.2e px", row.vertex_error_px);
    line += numbers;
  }
  line += ", image error " + std::to_string(row.image_error_px) + " px";
  return line;
}

}  // namespace twinraster::bench_report
