#include "base/counted.hpp"
#include "bench_report/bench_tables.hpp"
#include "gpu/draw_batches.hpp"

#include <nlohmann/json.hpp>

#include <array>
#include <cstdio>
#include <sstream>

namespace twinraster::bench_report {

namespace {

// Each stage's key in the CSV and JSON, in the order the bench measures them.
struct Stage {
  const char* key;
  const char* label;
  double bench::ScaleRow::*value;
};
constexpr std::array<Stage, 9> kStages = {{
    {"load_ms", "load", &bench::ScaleRow::load_ms},
    {"chain_ms", "host chain", &bench::ScaleRow::chain_ms},
    {"gpu_setup_ms", "gpu set-up", &bench::ScaleRow::gpu_setup_ms},
    {"gpu_draw_ms", "gpu draw", &bench::ScaleRow::gpu_draw_ms},
    {"gpu_per_draw_ms", "gpu, F per draw", &bench::ScaleRow::gpu_per_draw_ms},
    {"twin_setup_ms", "twin set-up", &bench::ScaleRow::twin_setup_ms},
    {"twin_draw_ms", "twin draw", &bench::ScaleRow::twin_draw_ms},
    {"png_ms", "png", &bench::ScaleRow::png_ms},
    {"verify_ms", "verify", &bench::ScaleRow::verify_ms},
}};

// The fixed costs: what a scene costs beyond its drawing, as whole processes.
void PutProcessTimes(std::ostringstream& s, const bench::ProcessTimes& p) {
  char line[256];
  s << "Fixed costs: whole processes, medians of " << Counted(p.runs, "run") << " in turn (the batch: " << p.batch_runs
    << ")\n";
  const auto put = [&](const char* what, double ms, const std::string& note) {
    std::snprintf(line, sizeof line, "  %-70s %9.1f ms  %s\n", what, ms, note.c_str());
    s << line;
  };
  char ratio[64];
  std::snprintf(ratio, sizeof ratio, "%.2fx the floor", p.floor_ms > 0 ? p.cpu_scene_ms / p.floor_ms : 0.0);
  put("twinraster --help (the process floor)", p.floor_ms, "");
  put("twinraster --version (asks the Vulkan loader for every device)", p.version_ms, "");
  put("render cgfs-transforms.json --backend cpu (600x600)", p.cpu_scene_ms, ratio);
  if (p.driver_floor_ms > 0) {
    put("twinraster --version, lavapipe's driver alone (the Vulkan floor)", p.driver_floor_ms, "");
  } else {
    s << "  (the Vulkan floor not measured: lavapipe is not installed, or the loader's variables choose the drivers)\n";
  }
  std::snprintf(ratio, sizeof ratio, "%.1f ms over the Vulkan floor", p.gpu_scene_ms - p.driver_floor_ms);
  put("render cgfs-transforms.json --backend gpu (child process included)", p.gpu_scene_ms,
      p.driver_floor_ms > 0 ? ratio : "");
  std::snprintf(ratio, sizeof ratio, "%.2f ms a scene",
                p.batch_scenes > 0 ? p.batch_ms / static_cast<double>(p.batch_scenes) : 0.0);
  const std::string batch = "render " + Counted(p.batch_scenes, "scene") + " " + std::to_string(p.batch_side) + "x" +
                            std::to_string(p.batch_side) + ", both backends, --report, --junit";
  put(batch.c_str(), p.batch_ms, ratio);
}

// MB of pixels (RGBA) encoded per second.
double PngMegabytesPerSecond(const bench::ScaleResult& result, const bench::PngEncoding& e) {
  return e.ms > 0 ? static_cast<double>(result.width) * result.height * 4 / 1e6 / (e.ms / 1e3) : 0;
}

void PutPngEncodings(std::ostringstream& s, const bench::ScaleResult& result) {
  s << "PNG: each size's frame (the twin's, " << result.width << "x" << result.height
    << ") by each encoder, medians of " << Counted(result.runs, "run") << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%10s  %-30s %9s %12s %9s\n", "instances", "encoder", "ms", "bytes", "MB/s");
  s << line;
  for (const bench::ScaleRow& r : result.rows) {
    for (const bench::PngEncoding& e : r.png_encoders) {
      std::snprintf(line, sizeof line, "%10zu  %-30s %9.2f %12zu %9.0f\n", r.instances, e.encoder.c_str(), e.ms,
                    e.bytes, PngMegabytesPerSecond(result, e));
      s << line;
    }
  }
  s << "(MB/s: megabytes of RGBA pixels in, per second; level 1's time includes its two threads)\n";
}

// The fixed costs and the PNG encoders, after the stages.
std::string ExtraTables(const bench::ScaleResult& result) {
  std::ostringstream s;
  if (result.processes) {
    PutProcessTimes(s, *result.processes);
  } else {
    s << "Fixed costs: not measured (the chapter's scene, cgfs-transforms.json, is not in --scenes DIR)\n";
  }
  if (!result.rows.empty() && !result.rows.front().png_encoders.empty()) {
    s << "\n";
    PutPngEncodings(s, result);
  }
  return s.str();
}

}  // namespace

std::string ScaleTable(const bench::ScaleResult& result) {
  std::ostringstream s;
  s << "Scale: cubes written out one instance each, medians of " << Counted(result.runs, "run") << "; "
    << result.machine << "\n";
  char line[256];
  std::snprintf(line, sizeof line, "%10s %10s %9s |%8s %8s %9s %9s %9s %9s %9s %7s %8s |%8s  %s\n", "instances",
                "triangles", "JSON MB", "load", "chain", "gpu setup", "gpu draw", "per-draw", "twin set", "twin draw",
                "png", "verify", "peak MB", "gpu == twin");
  s << line;
  for (const bench::ScaleRow& r : result.rows) {
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
    << Counted(result.rows.empty() ? 0 : result.rows.front().threads, "thread")
    << "; verify: the verifier judging the twin's image; peak MB: the process's peak resident memory after "
       "that size)\n";
  const std::string extra = ExtraTables(result);
  if (!extra.empty()) s << "\n" << extra;
  return s.str();
}

std::string ScaleCsv(const bench::ScaleResult& result) {
  std::ostringstream s;
  s << "instances,triangles,json_bytes,threads";
  for (const Stage& stage : kStages) s << "," << stage.key;
  s << ",peak_mib,identical\n";
  for (const bench::ScaleRow& r : result.rows) {
    s << r.instances << "," << r.triangles << "," << r.json_bytes << "," << r.threads;
    for (const Stage& stage : kStages) s << "," << r.*stage.value;
    s << "," << r.peak_mib << "," << (r.identical ? "true" : "false") << "\n";
  }
  return s.str();
}

nlohmann::ordered_json ScaleJson(const bench::ScaleResult& result) {
  nlohmann::ordered_json j;
  j["format"] = kScaleJsonFormat;
  j["machine"] = result.machine;
  j["runs"] = result.runs;
  j["rows"] = nlohmann::ordered_json::array();
  for (const bench::ScaleRow& r : result.rows) {
    nlohmann::ordered_json row;
    row["instances"] = r.instances;
    row["triangles"] = r.triangles;
    row["json_bytes"] = r.json_bytes;
    row["threads"] = r.threads;
    for (const Stage& stage : kStages) row[stage.key] = r.*stage.value;
    row["peak_mib"] = r.peak_mib;
    row["identical"] = r.identical;
    row["png_encoders"] = nlohmann::ordered_json::array();
    for (const bench::PngEncoding& e : r.png_encoders) {
      row["png_encoders"].push_back(
          {{"encoder", e.encoder}, {"ms", e.ms}, {"bytes", e.bytes}, {"mb_per_s", PngMegabytesPerSecond(result, e)}});
    }
    j["rows"].push_back(std::move(row));
  }
  j["processes"] = nullptr;
  if (const auto& p = result.processes) {
    j["processes"] = {
        {"runs", p->runs},
        {"floor_ms", p->floor_ms},
        {"version_ms", p->version_ms},
        {"driver_floor_ms", p->driver_floor_ms > 0 ? nlohmann::ordered_json(p->driver_floor_ms) : nullptr},
        {"cpu_scene_ms", p->cpu_scene_ms},
        {"gpu_scene_ms", p->gpu_scene_ms},
        {"cpu_scene_over_floor", p->floor_ms > 0 ? p->cpu_scene_ms / p->floor_ms : 0.0},
        {"batch_scenes", p->batch_scenes},
        {"batch_side", p->batch_side},
        {"batch_runs", p->batch_runs},
        {"batch_ms", p->batch_ms}};
  }
  return j;
}

}  // namespace twinraster::bench_report
