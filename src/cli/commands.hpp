// The subcommands of the twinraster executable: each declares its arguments on the parser and
// returns what runs it once the command line is parsed.
#pragma once

#include <functional>

namespace CLI {
class App;  // CLI11 itself is included only by the .cpp files: it is a large header
}

namespace twinraster::run {
enum class Verdict;
}

namespace twinraster {

// Exit codes shared by every command.
enum ExitCode : int {
  kExitOk = 0,
  kExitImagesDiffer = 1,
  kExitBadInput = 2,
  kExitNoVulkan = 3,
  kExitInternalError = 4,
  kExitGpuFailed = 5,     // the Vulkan driver crashed or timed out; everything else was still done
  kExitInconclusive = 6,  // no pixel is wrong, but the verifier could not tell a correct image from a broken one
};

// The exit code of one scene's verdict (run/verdict.hpp): crashed 5, differing 1,
// inconclusive 6, an error 2, anything else 0.
int ExitCodeOf(run::Verdict verdict);

// Of two scenes' exit codes, the one a batch reports: any problem outranks an inconclusive
// judgement, which outranks success.
int WorseExit(int a, int b);

// Runs a parsed command and returns the exit code; throws SceneError, FileError, UsageError or
// GpuUnavailable for main() to report.
using CommandRun = std::function<int()>;

CommandRun AddExplainCommand(CLI::App& app);
CommandRun AddRenderCommand(CLI::App& app);
CommandRun AddCompareCommand(CLI::App& app);
CommandRun AddVerifyCommand(CLI::App& app);
CommandRun AddBenchCommand(CLI::App& app);

}  // namespace twinraster
