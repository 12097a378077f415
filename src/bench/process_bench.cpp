#include "bench/process_bench.hpp"

#include "base/stopwatch.hpp"
#include "bench/bench_suite.hpp"
#include "gpu/driver_files.hpp"

#include <fcntl.h>
#include <nlohmann/json.hpp>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <vector>

extern char** environ;

namespace twinraster::bench {

double TimedProcess(const std::vector<std::string>& args, int expected_exit) {
  std::vector<char*> argv;
  for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t files;
  posix_spawn_file_actions_init(&files);
  posix_spawn_file_actions_addopen(&files, STDOUT_FILENO, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&files, STDERR_FILENO, "/dev/null", O_WRONLY, 0);
  Stopwatch clock;
  pid_t pid = 0;
  const int failed = posix_spawn(&pid, argv[0], &files, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&files);
  if (failed != 0) throw std::runtime_error("bench: cannot start " + args[0] + ": " + std::strerror(failed));
  int status = 0;
  while (waitpid(pid, &status, 0) < 0 && errno == EINTR) {
  }
  const double ms = clock.Milliseconds();
  if (!WIFEXITED(status) || WEXITSTATUS(status) != expected_exit) {
    std::string command;
    for (const std::string& arg : args) command += (command.empty() ? "" : " ") + arg;
    throw std::runtime_error("bench: `" + command + "` did not exit " + std::to_string(expected_exit));
  }
  return ms;
}

std::optional<std::uint64_t> PeakResidentKib(const std::vector<std::string>& args, int expected_exit) {
  const std::filesystem::path time = "/usr/bin/time";
  if (access(time.c_str(), X_OK) != 0) return std::nullopt;
  const TemporaryDirectory work;
  const std::filesystem::path report = work.path() / "time.txt";
  std::vector<std::string> timed = {time.string(), "-f", "%M", "-o", report.string()};
  timed.insert(timed.end(), args.begin(), args.end());
  TimedProcess(timed, expected_exit);  // time exits as its command did
  std::ifstream in(report);
  std::uint64_t kib = 0;
  if (!(in >> kib)) throw std::runtime_error("bench: /usr/bin/time wrote no peak memory for " + args[0]);
  return kib;
}

TemporaryDirectory::TemporaryDirectory() {
  std::string pattern = (std::filesystem::temp_directory_path() / "twinraster-bench-XXXXXX").string();
  if (!mkdtemp(pattern.data())) throw std::runtime_error("bench: cannot make a temporary directory");
  path_ = pattern;
}

TemporaryDirectory::~TemporaryDirectory() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

namespace {

// The chapter's scene at side x side, the camera stepped sideways through ten places, `count`
// times: the batch, as a test suite of small scenes has it.
std::vector<std::string> WriteBatchScenes(const ProcessBenchOptions& options, const std::filesystem::path& directory) {
  std::ifstream in(options.chapter_scene);
  nlohmann::json scene = nlohmann::json::parse(in);
  scene["canvas"]["width"] = options.batch_side;
  scene["canvas"]["height"] = options.batch_side;
  const double x = scene["camera"]["position"][0].get<double>();
  std::vector<std::string> files;
  for (std::size_t i = 0; i < options.batch_scenes; ++i) {
    scene["camera"]["position"][0] = x + 0.1 * static_cast<double>(i % 10);
    const std::string name = "s" + std::to_string(i) + ".json";
    std::ofstream(directory / name) << scene.dump();
    files.push_back((directory / name).string());
  }
  return files;
}

}  // namespace

ProcessTimes RunProcessBench(const ProcessBenchOptions& options) {
  const TemporaryDirectory work;
  const std::string exe = options.executable.string(), scene = options.chapter_scene.string();
  const std::string out = (work.path() / "out.png").string();
  std::vector<double> floor, version, driver_floor, cpu, gpu;
  for (int run = 0; run < options.runs; ++run) {  // in turn, so that the machine's drift is shared
    floor.push_back(TimedProcess({exe, "--help"}));
    version.push_back(TimedProcess({exe, "--version"}));
    {
      const gpu::LavapipeAlone alone;  // in this process's environment, which the child inherits
      if (!alone.manifest().empty()) driver_floor.push_back(TimedProcess({exe, "--version"}));
    }
    cpu.push_back(TimedProcess({exe, "render", "-q", scene, "--backend", "cpu", "-o", out}));
    gpu.push_back(TimedProcess({exe, "render", "-q", scene, "--backend", "gpu", "-o", out}));
  }
  const std::filesystem::path scenes = work.path() / "scenes";
  std::filesystem::create_directory(scenes);
  const std::vector<std::string> files = WriteBatchScenes(options, scenes);
  std::vector<double> batch;
  for (int run = 0; run < options.batch_runs; ++run) {
    // Fresh directories each run: replacing files deleted moments before costs the file system
    // more (docs/fixed-costs.md).
    const std::filesystem::path to = work.path() / ("batch-" + std::to_string(run));
    std::vector<std::string> args = {exe, "render", "-q"};
    args.insert(args.end(), files.begin(), files.end());
    for (const std::string& extra :
         std::vector<std::string>{"-o", (to / "out").string(), "--report", (to / "report").string(), "--junit",
                                  (to / "junit.xml").string()}) {
      args.push_back(extra);
    }
    batch.push_back(TimedProcess(args));
  }
  return {.floor_ms = Median(floor),
          .version_ms = Median(version),
          .driver_floor_ms = driver_floor.empty() ? 0 : Median(driver_floor),
          .cpu_scene_ms = Median(cpu),
          .gpu_scene_ms = Median(gpu),
          .batch_ms = batch.empty() ? 0 : Median(batch),
          .runs = options.runs,
          .batch_runs = options.batch_runs,
          .batch_scenes = options.batch_scenes,
          .batch_side = options.batch_side};
}

}  // namespace twinraster::bench
