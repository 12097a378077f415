// What a scene costs beyond its drawing, timed as a user meets it: whole twinraster processes
// (started, waited for, wall time), side by side in rounds, medians. The process floor
// (`--help`), the Vulkan floor, the chapter's scene rendered on each backend, and a batch of small
// scenes on both backends with its page and JUnit file; and the helpers bench --verify times its
// processes with. It does not time stages inside a process (scale_bench does), and it checks only
// that each process exits as expected.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::bench {

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
  double floor_ms = 0;    // twinraster --help: starting and ending the program
  double version_ms = 0;  // twinraster --version, which asks the Vulkan loader for every device
  // twinraster --version with lavapipe's driver alone offered to the loader: the Vulkan floor under
  // a gpu render (the driver loaded and its device found, nothing drawn); 0 when not measured
  // (lavapipe not installed, or the user's loader variables choose the drivers).
  double driver_floor_ms = 0;
  double cpu_scene_ms = 0, gpu_scene_ms = 0;  // render SCENE --backend cpu / gpu -o OUT.png
  double batch_ms = 0;                        // render of batch_scenes scenes, --backend both, --report and --junit
  int runs = 0, batch_runs = 0;
  std::size_t batch_scenes = 0;
  std::uint32_t batch_side = 0;
};

// Works in a temporary directory, removed afterwards. Throws std::runtime_error when a process
// cannot start or exits other than 0.
ProcessTimes RunProcessBench(const ProcessBenchOptions& options);

// Runs `args` (args[0] the executable) with its output thrown away, and returns its wall time in
// milliseconds, from start to exit. Throws std::runtime_error when it cannot start, or when it does
// not exit with `expected_exit`.
double TimedProcess(const std::vector<std::string>& args, int expected_exit = 0);

// The peak resident memory of `args` run once, in KiB, as `/usr/bin/time -f %M` reports it; empty
// when /usr/bin/time is not installed (Debian's package time). Not from this process's own wait:
// a child spawned from a large process inherits that process's peak (Linux keeps the larger of
// the peak before and after exec), so a small process must start it. Throws as TimedProcess.
std::optional<std::uint64_t> PeakResidentKib(const std::vector<std::string>& args, int expected_exit = 0);

// A fresh directory under the system's temporary one, removed with this object.
class TemporaryDirectory {
 public:
  TemporaryDirectory();
  ~TemporaryDirectory();
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

}  // namespace twinraster::bench
