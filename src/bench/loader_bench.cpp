#include "bench/loader_bench.hpp"

#include "base/stopwatch.hpp"
#include "bench/bench_suite.hpp"
#include "bench/scene_json_writer.hpp"
#include "chain/matrices.hpp"
#include "scene/obj_scene.hpp"

#include <malloc.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <fstream>
#include <stdexcept>
#include <string>

namespace twinraster::bench {

namespace {

// A line "Key:   123 kB" of /proc/self/status, in bytes.
std::uint64_t StatusBytes(const char* key) {
  std::ifstream status("/proc/self/status");
  const std::string prefix = std::string(key) + ":";
  for (std::string line; std::getline(status, line);) {
    if (line.rfind(prefix, 0) == 0) return std::stoull(line.substr(prefix.size())) * 1024;
  }
  return 0;
}

std::uint64_t HeapInUse() {
  const struct mallinfo2 info = mallinfo2();
  return info.uordblks + info.hblkhd;  // the arena's chunks in use, and those mapped on their own
}

struct LoadMemory {
  std::uint64_t peak_rss_bytes = 0, scene_heap_bytes = 0;
};

// One load in a forked child, so that each starts from the same heap and its peak is its own.
LoadMemory MeasureLoadInChild(const std::filesystem::path& file) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) throw std::runtime_error("bench --loaders: cannot make a pipe");
  const pid_t pid = fork();
  if (pid < 0) throw std::runtime_error("bench --loaders: cannot fork");
  if (pid == 0) {
    close(pipe_ends[0]);
    std::uint64_t measured[2] = {0, 0};
    int exit_code = 1;
    try {
      malloc_trim(0);  // pages the parent freed are given back, so that reusing them counts
      // Writing 5 resets the peak (VmHWM) to the present resident size (Linux 4.0 and later).
      std::ofstream("/proc/self/clear_refs") << "5";
      const std::uint64_t resident = StatusBytes("VmHWM"), heap = HeapInUse();
      {
        const Scene scene = LoadSceneOrObj(file);
        measured[1] = HeapInUse() - heap;
        measured[0] = StatusBytes("VmHWM") - resident;
      }
      exit_code = 0;
    } catch (...) {
    }
    const ssize_t written = write(pipe_ends[1], measured, sizeof measured);
    _exit(written == sizeof measured ? exit_code : 1);
  }
  close(pipe_ends[1]);
  std::uint64_t measured[2] = {0, 0};
  const ssize_t got = read(pipe_ends[0], measured, sizeof measured);
  close(pipe_ends[0]);
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  if (got != sizeof measured || !WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw std::runtime_error("bench --loaders: the child loading " + file.string() + " failed");
  return {measured[0], measured[1]};
}

std::uint64_t MedianBytes(const std::vector<std::uint64_t>& values) {
  std::vector<double> d(values.begin(), values.end());
  return static_cast<std::uint64_t>(Median(d));
}

// The JSON file's Scene against the glTF file's: counts, then the largest differences. The JSON
// file names model m "m<m>" (scene_json_writer.hpp); its loader keeps its own order.
void Compare(const Scene& gltf, const Scene& json, LoaderRow& row) {
  row.same_counts = gltf.models.size() == json.models.size() && gltf.instances.size() == json.instances.size();
  if (!row.same_counts) return;
  std::vector<std::size_t> in_json(gltf.models.size(), json.models.size());
  for (std::size_t m = 0; m < json.models.size(); ++m) {
    const std::size_t written = std::stoul(json.models[m].name.substr(1));
    if (written < in_json.size()) in_json[written] = m;
  }
  for (std::size_t m = 0; row.same_counts && m < gltf.models.size(); ++m) {
    row.same_counts = in_json[m] < json.models.size();
    if (!row.same_counts) return;
    const Model &a = gltf.models[m], &b = json.models[in_json[m]];
    row.same_counts = a.vertices.size() == b.vertices.size() && a.triangles.size() == b.triangles.size();
    for (std::size_t v = 0; row.same_counts && v < a.vertices.size(); ++v) {
      for (int k = 0; k < 3; ++k)
        row.max_vertex_difference = std::max(row.max_vertex_difference, std::abs(a.vertices[v][k] - b.vertices[v][k]));
    }
  }
  for (std::size_t i = 0; row.same_counts && i < gltf.instances.size(); ++i) {
    row.same_counts = in_json[gltf.instances[i].model] == json.instances[i].model;
    const glm::dmat4 a = ModelMatrix(gltf.instances[i].transform), b = ModelMatrix(json.instances[i].transform);
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        row.max_model_matrix_difference = std::max(row.max_model_matrix_difference, std::abs(a[c][r] - b[c][r]));
  }
}

}  // namespace

LoaderBenchResult RunLoaderBench(const LoaderBenchOptions& options) {
  LoaderBenchResult result;
  result.asset = options.gltf.string();
  result.machine = MachineDescription("not used");
  result.runs = options.runs;
  result.memory_runs = options.memory_runs;

  const Scene scene = LoadSceneOrObj(options.gltf);
  result.models = scene.models.size();
  result.instances = scene.instances.size();
  for (const Model& model : scene.models) {
    result.vertices += model.vertices.size();
    result.triangles += model.triangles.size();
  }
  for (const Instance& instance : scene.instances)
    result.drawn_triangles += scene.models[instance.model].triangles.size();

  const TemporaryDirectory work;
  std::vector<std::filesystem::path> files = {options.gltf};
  std::string extension = options.gltf.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return std::tolower(c); });
  result.rows.emplace_back();
  result.rows.back().loader = extension == ".glb" ? "glb" : "gltf";
  for (const auto& [name, digits] :
       {std::pair{"json-exact", JsonDigits::kExact}, std::pair{"json-float", JsonDigits::kFloat}}) {
    const std::filesystem::path file = work.path() / (std::string(name) + ".json");
    std::ofstream(file, std::ios::binary) << SceneAsJson(scene, digits);
    files.push_back(file);
    LoaderRow row;
    row.loader = name;
    Compare(scene, LoadSceneOrObj(file), row);
    result.rows.push_back(row);
  }
  for (std::size_t f = 0; f < files.size(); ++f) result.rows[f].bytes = std::filesystem::file_size(files[f]);

  // In turn, so that the machine's drift falls on every file alike; one load each first, untimed.
  for (const auto& file : files) LoadSceneOrObj(file);
  std::vector<std::vector<double>> load_ms(files.size());
  for (int run = 0; run < options.runs; ++run) {
    for (std::size_t f = 0; f < files.size(); ++f) {
      Stopwatch clock;
      const Scene loaded = LoadSceneOrObj(files[f]);
      load_ms[f].push_back(clock.Milliseconds());
    }
  }
  std::vector<std::vector<std::uint64_t>> peak(files.size()), heap(files.size());
  for (int run = 0; run < options.memory_runs; ++run) {
    for (std::size_t f = 0; f < files.size(); ++f) {
      const LoadMemory memory = MeasureLoadInChild(files[f]);
      peak[f].push_back(memory.peak_rss_bytes);
      heap[f].push_back(memory.scene_heap_bytes);
    }
  }
  for (std::size_t f = 0; f < files.size(); ++f) {
    result.rows[f].load_ms = Median(load_ms[f]);
    result.rows[f].peak_rss_bytes = MedianBytes(peak[f]);
    result.rows[f].scene_heap_bytes = MedianBytes(heap[f]);
  }

  if (!options.executable.empty()) {
    const std::string exe = options.executable.string(), out = (work.path() / "out.png").string();
    // The floor, then render and explain of every file: timed in turn, then their peak memory
    // through /usr/bin/time in turn.
    std::vector<std::vector<std::string>> commands = {{exe, "--help"}};
    for (const auto& file : files) {
      commands.push_back({exe, "render", "-q", file.string(), "--backend", "cpu", "-o", out});
      commands.push_back({exe, "explain", file.string(), "--json"});
    }
    std::vector<std::vector<double>> ms(commands.size()), kib(commands.size());
    for (int run = 0; run < options.runs; ++run) {
      for (std::size_t c = 0; c < commands.size(); ++c) ms[c].push_back(TimedProcess(commands[c]));
    }
    for (int run = 0; run < options.memory_runs; ++run) {
      for (std::size_t c = 0; c < commands.size(); ++c) {
        if (const std::optional<std::uint64_t> kib_used = PeakResidentKib(commands[c]))
          kib[c].push_back(static_cast<double>(*kib_used));
      }
    }
    const auto cost = [&](std::size_t c) {
      ProcessCost measured{.ms = Median(ms[c]), .max_rss_kib = std::nullopt};
      if (!kib[c].empty()) measured.max_rss_kib = static_cast<std::uint64_t>(Median(kib[c]));
      return measured;
    };
    result.floor = cost(0);
    for (std::size_t f = 0; f < files.size(); ++f)
      result.rows[f].processes = LoaderProcesses{.render = cost(1 + 2 * f), .explain = cost(2 + 2 * f)};
  }
  return result;
}

}  // namespace twinraster::bench
