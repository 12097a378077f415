// `twinraster bench --loaders`: what loading a scene costs by its file format: a glTF asset (by
// default Debian's 2CylinderEngine.glb) against the same Scene written as a JSON scene file, side by
// side in one run: load time (file to Scene, in process, medians), memory (each load in a forked
// child: its peak resident memory's growth and the heap its Scene holds), and whole processes
// (`render --backend cpu`, `explain --json`: wall time and peak resident memory). It does not time
// anything after the Scene (the chain, the draw), which bench and bench --scale measure.
#pragma once

#include "bench/process_bench.hpp"

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::bench {

// Debian's assimp-testmodels asset (scripts/setup.sh --tests installs it): 115 instances of 29
// meshes, read from the system and never copied into the repository.
inline constexpr const char* kDefaultLoaderBenchAsset =
    "/usr/share/assimp/models/glTF2/2CylinderEngine-glTF-Binary/2CylinderEngine.glb";

struct LoaderBenchOptions {
  std::filesystem::path gltf;        // a .glb or .gltf file
  int runs = 15;                     // timed loads of each file, in turn; and whole processes of each
  int memory_runs = 5;               // forked children per file; /usr/bin/time runs per process
  std::filesystem::path executable;  // twinraster itself, for the whole processes; empty: not measured
};

// A whole process: its wall time, median of `runs` in turn, and its peak resident memory, median of
// `memory_runs` more (PeakResidentKib: empty without /usr/bin/time).
struct ProcessCost {
  double ms = 0;
  std::optional<std::uint64_t> max_rss_kib;
};

// Whole processes of one file.
struct LoaderProcesses {
  ProcessCost render;   // render -q FILE --backend cpu -o OUT.png
  ProcessCost explain;  // explain FILE --json, its output thrown away
};

struct LoaderRow {
  std::string loader;       // "glb" or "gltf"; "json-exact"; "json-float" (scene_json_writer.hpp)
  std::uint64_t bytes = 0;  // the file
  double load_ms = 0;       // LoadSceneOrObj, file to Scene, median
  // Medians over forked children, each loading the file once: VmHWM's growth over the load (the
  // peak reset through /proc/self/clear_refs first), and the heap the Scene holds afterwards
  // (mallinfo2, in use after less in use before).
  std::uint64_t peak_rss_bytes = 0, scene_heap_bytes = 0;
  // Against the glTF file's own Scene (0 for its row): the same models, vertices, triangles and
  // instances; the largest vertex coordinate's and M_Model entry's difference.
  bool same_counts = true;
  double max_vertex_difference = 0, max_model_matrix_difference = 0;
  std::optional<LoaderProcesses> processes;
};

struct LoaderBenchResult {
  std::string asset;                                                   // the glTF file as given
  std::size_t models = 0, instances = 0, vertices = 0, triangles = 0;  // the Scene's, stored once
  std::size_t drawn_triangles = 0;                                     // over every instance
  std::vector<LoaderRow> rows;                                         // the glTF file first, then the JSON files
  std::optional<ProcessCost> floor;  // twinraster --help, when processes were measured
  std::string machine;
  int runs = 0, memory_runs = 0;
};

// Writes the JSON files into a temporary directory, removed afterwards. Throws SceneError for a
// file that does not load, std::runtime_error when a child or a process fails.
LoaderBenchResult RunLoaderBench(const LoaderBenchOptions& options);

}  // namespace twinraster::bench
