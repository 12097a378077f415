// The subcommands of the twinraster executable; each returns the process exit code and throws
// SceneError, FileError or UsageError for the caller to report.
#pragma once

#include <string>
#include <vector>

namespace twinraster {

// Exit codes shared by every command.
enum ExitCode : int {
  kExitOk = 0,
  kExitImagesDiffer = 1,
  kExitBadInput = 2,
  kExitNoVulkan = 3,
  kExitInternalError = 4,
};

int ExplainCommand(const std::vector<std::string>& args);
int RenderCommand(const std::vector<std::string>& args);
int CompareCommand(const std::vector<std::string>& args);
int BenchCommand(const std::vector<std::string>& args);

}  // namespace twinraster
