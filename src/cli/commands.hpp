// The subcommands of the twinraster executable: each declares its arguments on the parser and
// returns what runs it once the command line is parsed.
#pragma once

#include "base/exit_code.hpp"

#include <functional>

namespace CLI {
class App;  // CLI11 itself is included only by the .cpp files: it is a large header
}

namespace twinraster::cli {

// Runs a parsed command and returns the exit code; throws SceneError, FileError, UsageError or
// GpuUnavailable for main() to report.
using CommandRun = std::function<int()>;

CommandRun AddExplainCommand(CLI::App& app);
CommandRun AddRenderCommand(CLI::App& app);
CommandRun AddCompareCommand(CLI::App& app);
CommandRun AddVerifyCommand(CLI::App& app);
CommandRun AddBenchCommand(CLI::App& app);

}  // namespace twinraster::cli
