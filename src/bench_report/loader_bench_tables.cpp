#include "base/counted.hpp"
#include "bench_report/bench_tables.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

namespace twinraster::bench_report {

namespace {

double PerTriangle(double value, const bench::LoaderBenchResult& result) {
  return result.triangles ? value / static_cast<double>(result.triangles) : 0.0;
}

double Ratio(double value, double reference) { return reference > 0 ? value / reference : 0.0; }

double Kib(std::uint64_t bytes) { return static_cast<double>(bytes) / 1024; }

std::string KibText(const bench::ProcessCost& cost) {
  return cost.max_rss_kib ? std::to_string(*cost.max_rss_kib) : "-";
}

nlohmann::ordered_json KibJson(const bench::ProcessCost& cost) {
  return cost.max_rss_kib ? nlohmann::ordered_json(*cost.max_rss_kib) : nlohmann::ordered_json(nullptr);
}

void PutProcesses(std::ostringstream& s, const bench::LoaderBenchResult& result) {
  s << "\nWhole processes: wall time, medians of " << Counted(result.runs, "run")
    << " in turn; peak resident memory by /usr/bin/time -f %M, medians of " << Counted(result.memory_runs, "run")
    << " (- without /usr/bin/time): render -q FILE --backend cpu -o OUT.png; explain FILE --json (its "
       "output thrown away)\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-20s | %10s %12s | %10s %12s\n", "file", "render ms", "max RSS KiB", "explain ms",
                "max RSS KiB");
  s << line;
  std::snprintf(line, sizeof line, "%-20s | %10.1f %12s | %10s %12s\n", "--help (the floor)", result.floor->ms,
                KibText(*result.floor).c_str(), "", "");
  s << line;
  for (const bench::LoaderRow& r : result.rows) {
    std::snprintf(line, sizeof line, "%-20s | %10.1f %12s | %10.1f %12s\n", r.loader.c_str(), r.processes->render.ms,
                  KibText(r.processes->render).c_str(), r.processes->explain.ms, KibText(r.processes->explain).c_str());
    s << line;
  }
}

}  // namespace

std::string LoaderBenchTable(const bench::LoaderBenchResult& result) {
  std::ostringstream s;
  s << "Loaders: one scene from each file, file to Scene (LoadSceneOrObj); time: medians of "
    << Counted(result.runs, "run") << " in turn; memory: medians of "
    << Counted(result.memory_runs, "forked child", "forked children") << " per file; " << result.machine << "\n";
  s << "asset " << result.asset << ": " << Counted(result.models, "model") << ", "
    << Counted(result.instances, "instance") << ", " << Counted(result.vertices, "vertex", "vertices") << ", "
    << Counted(result.triangles, "triangle") << " stored (" << result.drawn_triangles << " drawn)\n";
  char line[320];
  std::snprintf(line, sizeof line, "%-10s %10s | %8s %8s %7s %6s | %9s %7s %6s | %9s %7s %6s | %s\n", "file", "bytes",
                "load ms", "ns/tri", "ns/B", "ratio", "peak KiB", "B/tri", "ratio", "heap KiB", "B/tri", "ratio",
                "same Scene?");
  s << line;
  const bench::LoaderRow& first = result.rows.front();
  for (const bench::LoaderRow& r : result.rows) {
    char same[96];
    if (&r == &first)
      std::snprintf(same, sizeof same, "(the reference)");
    else if (!r.same_counts)
      std::snprintf(same, sizeof same, "no: other counts");
    else
      std::snprintf(same, sizeof same, "vertices within %.1e, M_Model within %.1e", r.max_vertex_difference,
                    r.max_model_matrix_difference);
    const double peak = static_cast<double>(r.peak_rss_bytes), heap = static_cast<double>(r.scene_heap_bytes);
    std::snprintf(line, sizeof line,
                  "%-10s %10llu | %8.2f %8.1f %7.2f %6.2f | %9.0f %7.1f %6.2f | %9.0f %7.1f %6.2f | %s\n",
                  r.loader.c_str(), static_cast<unsigned long long>(r.bytes), r.load_ms,
                  PerTriangle(r.load_ms * 1e6, result), r.bytes ? r.load_ms * 1e6 / static_cast<double>(r.bytes) : 0.0,
                  Ratio(r.load_ms, first.load_ms), Kib(r.peak_rss_bytes), PerTriangle(peak, result),
                  Ratio(peak, static_cast<double>(first.peak_rss_bytes)), Kib(r.scene_heap_bytes),
                  PerTriangle(heap, result), Ratio(heap, static_cast<double>(first.scene_heap_bytes)), same);
    s << line;
  }
  s << "(per triangle: of the " << result.triangles
    << " stored; ratio: against the first row; peak: VmHWM's growth over the load; heap: what the Scene holds "
       "after it (mallinfo2); json-exact: every number as the double it is, json-float: vertices as the shortest "
       "float, as the glTF file stores them)\n";
  if (result.floor) PutProcesses(s, result);
  return s.str();
}

nlohmann::ordered_json LoaderBenchJson(const bench::LoaderBenchResult& result) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  const bench::LoaderRow& first = result.rows.front();
  for (const bench::LoaderRow& r : result.rows) {
    const double peak = static_cast<double>(r.peak_rss_bytes), heap = static_cast<double>(r.scene_heap_bytes);
    nlohmann::ordered_json processes = nullptr;
    if (r.processes) {
      processes = {{"render_ms", r.processes->render.ms},
                   {"render_max_rss_kib", KibJson(r.processes->render)},
                   {"explain_ms", r.processes->explain.ms},
                   {"explain_max_rss_kib", KibJson(r.processes->explain)}};
    }
    rows.push_back({{"loader", r.loader},
                    {"bytes", r.bytes},
                    {"load_ms", r.load_ms},
                    {"load_ns_per_triangle", PerTriangle(r.load_ms * 1e6, result)},
                    {"load_ns_per_byte", r.bytes ? r.load_ms * 1e6 / static_cast<double>(r.bytes) : 0.0},
                    {"load_ratio", Ratio(r.load_ms, first.load_ms)},
                    {"peak_rss_bytes", r.peak_rss_bytes},
                    {"peak_rss_bytes_per_triangle", PerTriangle(peak, result)},
                    {"peak_rss_ratio", Ratio(peak, static_cast<double>(first.peak_rss_bytes))},
                    {"scene_heap_bytes", r.scene_heap_bytes},
                    {"scene_heap_bytes_per_triangle", PerTriangle(heap, result)},
                    {"scene_heap_ratio", Ratio(heap, static_cast<double>(first.scene_heap_bytes))},
                    {"same_counts", r.same_counts},
                    {"max_vertex_difference", r.max_vertex_difference},
                    {"max_model_matrix_difference", r.max_model_matrix_difference},
                    {"processes", processes}});
  }
  nlohmann::ordered_json floor = nullptr;
  if (result.floor) floor = {{"help_ms", result.floor->ms}, {"help_max_rss_kib", KibJson(*result.floor)}};
  return {{"format", kLoaderBenchJsonFormat},
          {"machine", result.machine},
          {"runs", result.runs},
          {"memory_runs", result.memory_runs},
          {"asset", result.asset},
          {"models", result.models},
          {"instances", result.instances},
          {"vertices", result.vertices},
          {"triangles", result.triangles},
          {"drawn_triangles", result.drawn_triangles},
          {"rows", rows},
          {"process_floor", floor}};
}

}  // namespace twinraster::bench_report
