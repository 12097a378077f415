// What every test executable shares: running the CLI as a user would, temp dirs, files, the
// shipped scenes.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace twinraster::test {

struct CliResult {
  int exit_code = -1;
  std::string out, err;
};

// `environment`: extra VAR=value settings for this run only. Standard input is /dev/null.
CliResult RunCli(const std::vector<std::string>& args, const std::vector<std::string>& environment = {});
// The same with `input` on standard input.
CliResult RunCliWithInput(const std::vector<std::string>& args, const std::string& input,
                          const std::vector<std::string>& environment = {});
// The CLI on a terminal: script(1) gives it a pseudo-terminal as standard input, output and error.
// `out` is everything it wrote there, standard output and error interleaved; `err` is script's own.
CliResult RunCliInTerminal(const std::vector<std::string>& args);

// A fresh empty directory under the system temp dir, removed when the object dies.
class TempDir {
 public:
  TempDir();
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }

 private:
  std::filesystem::path path_;
};

// Work to do when the test run ends, before main returns: objects that must not be destroyed by a
// static destructor (a Vulkan device, after the driver's own exit handlers have run) are released
// here, in the reverse order of registration.
void AtEndOfRun(std::function<void()> work);
void RunEndOfRunWork();  // main() calls it once

std::string ReadFile(const std::filesystem::path& file);
void WriteFile(const std::filesystem::path& file, const std::string& text);
std::filesystem::path SourcePath(const std::string& relative);  // inside the source tree
std::vector<std::filesystem::path> ShippedScenes();             // scenes/**/*.json but the large ones, sorted
std::vector<std::filesystem::path> LargeShippedScenes();        // the million-instance scenes, sorted

}  // namespace twinraster::test
