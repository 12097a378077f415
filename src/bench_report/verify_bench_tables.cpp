#include "base/counted.hpp"
#include "bench_report/bench_tables.hpp"

#include <nlohmann/json.hpp>

#include <cstdio>
#include <filesystem>
#include <sstream>

namespace twinraster::bench_report {

namespace {

// The same scenes as whole processes: what a user running `render` and then `verify` waits for.
void PutProcesses(std::ostringstream& s, const bench::VerifyBenchResult& result) {
  s << "\nWhole processes, medians of " << Counted(result.runs, "run")
    << " in turn: render SCENE --backend cpu -o OUT.png; verify SCENE IMAGE.png of the twin's image "
       "(passes) and of it shifted one pixel right (fails)\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-36s | %9s | %12s %6s | %12s %6s\n", "scene", "render ms", "verify ms", "ratio",
                "verify ms", "ratio");
  s << line;
  std::snprintf(line, sizeof line, "%-36s | %9s | %19s | %19s\n", "", "", "passing", "failing");
  s << line;
  for (const bench::VerifyProcessRow& r : result.processes) {
    std::snprintf(line, sizeof line, "%-36s | %9.1f | %12.1f %6.2f | %12.1f %6.2f\n",
                  std::filesystem::path(r.scene).filename().string().c_str(), r.render_ms, r.verify_passing_ms,
                  r.PassingRatio(), r.verify_failing_ms, r.FailingRatio());
    s << line;
  }
}

}  // namespace

std::string VerifyBenchTable(const bench::VerifyBenchResult& result) {
  std::ostringstream s;
  s << "Verify: the twin's render against the verifier's judgement of it, medians of " << Counted(result.runs, "run")
    << "; " << result.machine << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%-36s %11s %10s | %9s %10s %6s | %10s %10s\n", "scene", "size", "triangles",
                "twin ms", "verify ms", "ratio", "uncertain", "violations");
  s << line;
  for (const bench::VerifyBenchRow& r : result.rows) {
    const std::string size = std::to_string(r.width) + "x" + std::to_string(r.height);
    const double percent = r.covered ? 100.0 * double(r.uncertain) / double(r.covered) : 0.0;
    char uncertain[32];
    std::snprintf(uncertain, sizeof uncertain, "%.2f %%", percent);
    std::snprintf(line, sizeof line, "%-36s %11s %10zu | %9.1f %10.1f %6.2f | %10s %10llu\n",
                  std::filesystem::path(r.scene).filename().string().c_str(), size.c_str(), r.triangles, r.twin_ms,
                  r.verify_ms, r.Ratio(), uncertain, static_cast<unsigned long long>(r.violations));
    s << line;
  }
  // The twin chooses its threads per scene (one for a small frame), so each row's are given.
  std::string threads;
  for (const bench::VerifyBenchRow& r : result.rows)
    threads += (threads.empty() ? "" : ", ") + std::to_string(r.twin_threads);
  s << "(twin: RenderOnCpu as render runs it, row by row, on each scene's threads: " << threads
    << "; verify: VerifyImage of that image at 8 subpixel bits, one band of rows per hardware "
       "thread; uncertain: of the covered pixels)\n";
  if (!result.processes.empty()) PutProcesses(s, result);
  return s.str();
}

nlohmann::ordered_json VerifyBenchJson(const bench::VerifyBenchResult& result) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (const bench::VerifyBenchRow& r : result.rows) {
    rows.push_back({{"scene", r.scene},
                    {"width", r.width},
                    {"height", r.height},
                    {"triangles", r.triangles},
                    {"twin_threads", r.twin_threads},
                    {"twin_ms", r.twin_ms},
                    {"verify_ms", r.verify_ms},
                    {"ratio", r.Ratio()},
                    {"uncertain", r.uncertain},
                    {"covered", r.covered},
                    {"violations", r.violations}});
  }
  nlohmann::ordered_json processes = nlohmann::ordered_json::array();
  for (const bench::VerifyProcessRow& r : result.processes) {
    processes.push_back({{"scene", r.scene},
                         {"render_ms", r.render_ms},
                         {"verify_passing_ms", r.verify_passing_ms},
                         {"passing_ratio", r.PassingRatio()},
                         {"verify_failing_ms", r.verify_failing_ms},
                         {"failing_ratio", r.FailingRatio()}});
  }
  return {{"format", "twinraster.bench-verify/2"},
          {"machine", result.machine},
          {"runs", result.runs},
          {"rows", rows},
          {"processes", processes}};
}

}  // namespace twinraster::bench_report
