// What a scene costs beyond its drawing, timed as a user meets it: whole twinraster processes
// (started, waited for, wall time), side by side in rounds, medians. The process floor
// (`--help`), the chapter's scene rendered on each backend, and a batch of small scenes on both
// backends with its page and JUnit file. It does not time stages inside a process (scale_bench
// does), and it checks only that each process exits 0.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>

namespace twinraster {

struct ProcessBenchOptions {
  std::filesystem::path executable;     // twinraster itself
  std::filesystem::path chapter_scene;  // scenes/cgfs-transforms.json
  int runs = 11;                        // of each single-scene process
  int batch_runs = 3;
  std::size_t batch_scenes = 1000;
  std::uint32_t batch_side = 64;  // pixels, square
};

struct ProcessTimes {
  // Medians, milliseconds, each a whole process.
  double floor_ms = 0;                        // twinraster --help: starting and ending the program
  double version_ms = 0;                      // twinraster --version, which asks the Vulkan loader for every device
  double cpu_scene_ms = 0, gpu_scene_ms = 0;  // render SCENE --backend cpu / gpu -o OUT.png
  double batch_ms = 0;                        // render of batch_scenes scenes, --backend both, --report and --junit
  int runs = 0, batch_runs = 0;
  std::size_t batch_scenes = 0;
  std::uint32_t batch_side = 0;
};

// Works in a temporary directory, removed afterwards. Throws std::runtime_error when a process
// cannot start or exits other than 0.
ProcessTimes RunProcessBench(const ProcessBenchOptions& options);

}  // namespace twinraster
