#include "support/test_support.hpp"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace twinraster::test {

namespace {
std::string ShellQuote(const std::string& s) {
  std::string q = "'";
  for (char c : s) q += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return q + "'";
}
}  // namespace

TempDir::TempDir() {
  static std::atomic<int> counter{0};
  path_ = std::filesystem::temp_directory_path() /
          ("twinraster-test-" + std::to_string(::getpid()) + "-" + std::to_string(counter++));
  std::filesystem::remove_all(path_);
  std::filesystem::create_directories(path_);
}

TempDir::~TempDir() {
  std::error_code ignored;
  std::filesystem::remove_all(path_, ignored);
}

namespace {
std::vector<std::function<void()>>& EndOfRunWork() {
  static std::vector<std::function<void()>> work;
  return work;
}
}  // namespace

void AtEndOfRun(std::function<void()> work) { EndOfRunWork().push_back(std::move(work)); }

void RunEndOfRunWork() {
  auto& work = EndOfRunWork();
  while (!work.empty()) {
    const std::function<void()> next = std::move(work.back());
    work.pop_back();
    next();
  }
}

std::string ReadFile(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

void WriteFile(const std::filesystem::path& file, const std::string& text) {
  std::ofstream out(file, std::ios::binary);
  out << text;
  if (!out) throw std::runtime_error("cannot write " + file.string());
}

std::filesystem::path SourcePath(const std::string& relative) {
  return std::filesystem::path(TWINRASTER_SOURCE_DIR) / relative;
}

namespace {
// Scenes too large to run through every per-scene test (a million instances); each has tests of
// its own, at a smaller canvas where rendering is involved.
const char* const kLargeScenes[] = {"scenes/one-million-cubes.json"};

bool IsLarge(const std::filesystem::path& file) {
  return std::any_of(std::begin(kLargeScenes), std::end(kLargeScenes),
                     [&](const char* large) { return file == SourcePath(large); });
}

std::vector<std::filesystem::path> SceneFiles(bool large) {
  std::vector<std::filesystem::path> scenes;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(SourcePath("scenes"))) {
    if (entry.is_regular_file() && entry.path().extension() == ".json" && IsLarge(entry.path()) == large) {
      scenes.push_back(entry.path());
    }
  }
  std::sort(scenes.begin(), scenes.end());
  return scenes;
}
}  // namespace

// How many of each the repository ships: a loop over them judges exactly these, never a list that
// a moved folder or a wrong pattern left empty. Adding or removing a scene changes the count here.
constexpr std::size_t kShippedSceneCount = 46;

std::vector<std::filesystem::path> ShippedScenes() {
  std::vector<std::filesystem::path> scenes = SceneFiles(false);
  if (scenes.size() != kShippedSceneCount) {
    throw std::logic_error("tests found " + std::to_string(scenes.size()) + " shipped scenes under scenes/, expected " +
                           std::to_string(kShippedSceneCount) + " (tests/support/test_support.cpp)");
  }
  return scenes;
}

std::vector<std::filesystem::path> LargeShippedScenes() {
  std::vector<std::filesystem::path> scenes = SceneFiles(true);
  if (scenes.size() != std::size(kLargeScenes)) {
    throw std::logic_error("tests found " + std::to_string(scenes.size()) + " of the " +
                           std::to_string(std::size(kLargeScenes)) + " large scenes (tests/support/test_support.cpp)");
  }
  return scenes;
}

namespace {

std::string CliCommand(const std::vector<std::string>& args, const std::vector<std::string>& environment) {
  std::string command = "env";
  for (const std::string& e : environment) command += " " + ShellQuote(e);
  command += " " + ShellQuote(TWINRASTER_EXE);
  for (const std::string& a : args) command += " " + ShellQuote(a);
  return command;
}

// Runs a shell command with its output and errors captured and `input` (a file) as its input.
CliResult RunShell(const std::string& command, const std::filesystem::path& input) {
  const TempDir dir;
  const std::string line = command + " >" + ShellQuote((dir / "out").string()) + " 2>" +
                           ShellQuote((dir / "err").string()) + " <" + ShellQuote(input.string());
  const int status = std::system(line.c_str());
  CliResult result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  result.out = ReadFile(dir / "out");
  result.err = ReadFile(dir / "err");
  return result;
}

}  // namespace

CliResult RunCli(const std::vector<std::string>& args, const std::vector<std::string>& environment) {
  return RunShell(CliCommand(args, environment), "/dev/null");
}

CliResult RunCliWithInput(const std::vector<std::string>& args, const std::string& input,
                          const std::vector<std::string>& environment) {
  const TempDir dir;
  WriteFile(dir / "input", input);
  return RunShell(CliCommand(args, environment), dir / "input");
}

CliResult RunCliInTerminal(const std::vector<std::string>& args) {
  // -q: no "Script started" lines; -e: script exits with the command's exit code.
  return RunShell("script -qec " + ShellQuote(CliCommand(args, {})) + " /dev/null", "/dev/null");
}

}  // namespace twinraster::test
