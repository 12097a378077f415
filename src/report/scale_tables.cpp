#include "gpu/draw_batches.hpp"
#include "report/bench_tables.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <sstream>

namespace twinraster::report {

namespace {

// Each stage's key in the CSV and JSON, in the order the bench measures them.
struct Stage {
  const char* key;
  const char* label;
  double ScaleRow::*value;
};
constexpr std::array<Stage, 9> kStages = {{
    {"load_ms", "load", &ScaleRow::load_ms},
    {"chain_ms", "host chain", &ScaleRow::chain_ms},
    {"gpu_setup_ms", "gpu set-up", &ScaleRow::gpu_setup_ms},
    {"gpu_draw_ms", "gpu draw", &ScaleRow::gpu_draw_ms},
    {"gpu_per_draw_ms", "gpu, F per draw", &ScaleRow::gpu_per_draw_ms},
    {"twin_setup_ms", "twin set-up", &ScaleRow::twin_setup_ms},
    {"twin_draw_ms", "twin draw", &ScaleRow::twin_draw_ms},
    {"png_ms", "png", &ScaleRow::png_ms},
    {"verify_ms", "verify", &ScaleRow::verify_ms},
}};

}  // namespace

std::string ScaleTable(const ScaleResult& result) {
  std::ostringstream s;
  s << "Scale: cubes written out one instance each, medians of " << result.runs << " run(s); " << result.machine
    << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%10s %10s %9s |%8s %8s %9s %9s %9s %9s %9s %7s %8s |%8s  %s\n", "instances",
                "triangles", "JSON MB", "load", "chain", "gpu setup", "gpu draw", "per-draw", "twin set", "twin draw",
                "png", "verify", "peak MB", "gpu == twin");
  s << line;
  for (const ScaleRow& r : result.rows) {
    std::snprintf(line, sizeof line,
                  "%10zu %10zu %9.1f |%8.1f %8.1f %9.1f %9.1f %9.1f %9.1f %9.1f %7.1f %8.1f |%8.0f  %s\n", r.instances,
                  r.triangles, static_cast<double>(r.json_bytes) / 1e6, r.load_ms, r.chain_ms, r.gpu_setup_ms,
                  r.gpu_draw_ms, r.gpu_per_draw_ms, r.twin_setup_ms, r.twin_draw_ms, r.png_ms, r.verify_ms, r.peak_mib,
                  r.identical ? "yes" : "NO");
    s << line;
  }
  s << "(milliseconds; per-draw: lavapipe's set-up + draw with F pushed per draw, against gpu set-up + draw as a user\n"
       " gets it, instanced from "
    << gpu::kInstancingThreshold << " draws of a mesh on; twin on "
    << (result.rows.empty() ? 0 : result.rows.front().threads)
    << " thread(s); verify: the verifier judging the twin's image; peak MB: the process's peak resident memory after "
       "that size)\n";
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

}  // namespace twinraster::report
