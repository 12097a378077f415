// twinraster's command line: explain a scene's transform chain, render it on Vulkan and on the
// CPU twin, compare images, bench. CLI11 parses it; every error becomes one message and an exit
// code.
#include "base/closest_match.hpp"
#include "base/usage_error.hpp"
#include "cli/commands.hpp"
#include "cli/parser_setup.hpp"
#include "cli/usage_problems.hpp"
#include "cli/version.hpp"
#include "files/staged_file.hpp"
#include "gpu/gpu_renderer.hpp"
#include "scene/scene_error.hpp"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <map>
#include <memory>
#include <string>

namespace {

using namespace twinraster;
using namespace twinraster::cli;  // main is global, as C++ requires: it reads the command line's names

// A mistake on the command line: one line saying what, and where to read how.
int ReportUsageError(const CLI::App* command, const std::string& problem) {
  const std::string name = command ? "twinraster " + command->get_name() : "twinraster";
  std::cerr << name << ": " << problem << "\nsee '" << name << " --help'\n";
  return kExitBadInput;
}

CLI::App* SelectedCommand(const CLI::App& app) {
  const std::vector<CLI::App*> selected = app.get_subcommands();
  return selected.empty() ? nullptr : selected.front();
}

// `twinraster help [COMMAND]`: the same text as --help.
CommandRun AddHelpCommand(CLI::App& app) {
  auto topic = std::make_shared<std::string>();
  CLI::App* command = AddSubcommand(app, "help", "print the usage of twinraster or of COMMAND", "");
  command->add_option("COMMAND", *topic, "the command to describe");
  return [&app, topic] {
    if (topic->empty()) {
      std::cout << app.get_formatter()->make_help(&app, app.get_name(), CLI::AppFormatMode::Normal);
      return int{kExitOk};
    }
    std::vector<std::string> names;
    for (const CLI::App* other : app.get_subcommands({})) {
      if (other->get_name() == *topic) {
        std::cout << other->help(app.get_name());
        return int{kExitOk};
      }
      names.push_back(other->get_name());
    }
    const std::string suggestion = ClosestMatch(*topic, names);
    throw UsageError("unknown command \"" + *topic + "\"" +
                     (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)"));
  };
}

int Run(int argc, char** argv) {
  CLI::App app(
      "twinraster: the transform chain of Computer Graphics from Scratch, chapter 10, drawn on\n"
      "Vulkan (lavapipe) and on a bit-exact CPU twin.",
      "twinraster");
  SetUpParser(app);
  // A function, called only when --version is given: it reaches Vulkan to list the devices.
  app.set_version_flag("--version", VersionText, "print the version and exit");
  app.footer(
      "Run 'twinraster COMMAND --help' for a command's arguments.\n"
      "Exit codes: 0 done (images identical, or verified), 1 images differ (or violate), 2 bad input or usage,\n"
      "3 no usable Vulkan device, 4 internal error, 5 the Vulkan driver crashed or timed out,\n"
      "6 inconclusive (the verifier found no violation but could not tell a broken image).");
  const std::map<std::string, CommandRun> commands = {
      {"explain", AddExplainCommand(app)}, {"render", AddRenderCommand(app)}, {"verify", AddVerifyCommand(app)},
      {"compare", AddCompareCommand(app)}, {"bench", AddBenchCommand(app)},   {"help", AddHelpCommand(app)},
  };

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp&) {
    std::cout << app.help();  // the selected command's help, if there is one
    return kExitOk;
  } catch (const CLI::CallForVersion& version) {
    std::cout << version.what() << "\n";
    return kExitOk;
  } catch (const CLI::ParseError& error) {
    // A stray argument explains most errors best (it is often why a value went missing).
    CLI::App* command = SelectedCommand(app);
    if (std::string p = LeftoverProblem(app); !p.empty()) return ReportUsageError(nullptr, p);
    if (command) {
      if (std::string p = LeftoverProblem(*command); !p.empty()) return ReportUsageError(command, p);
      if (std::string p = MissingArgumentProblem(*command); !p.empty()) return ReportUsageError(command, p);
    }
    return ReportUsageError(command, ParseErrorProblem(error));
  }
  CLI::App* command = SelectedCommand(app);
  if (std::string p = LeftoverProblem(app); !p.empty()) return ReportUsageError(nullptr, p);
  // A bare `twinraster` is most often someone finding out what it does: the usage says more than
  // "missing command" would. Still a mistake for a script, so on standard error, exit 2.
  if (!command) {
    std::cerr << app.help();
    return kExitBadInput;
  }
  if (std::string p = LeftoverProblem(*command); !p.empty()) return ReportUsageError(command, p);
  try {
    return commands.at(command->get_name())();
  } catch (const UsageError& e) {
    return ReportUsageError(command, e.what());
  }
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(argc, argv);
  } catch (const SceneError& e) {
    std::cerr << "twinraster: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const files::FileError& e) {
    std::cerr << "twinraster: " << e.what() << "\n";
    return kExitBadInput;
  } catch (const gpu::GpuUnavailable& e) {
    if (!gpu::VulkanInBuild()) {  // no device could ever be usable: say so in one line
      std::cerr << "twinraster: " << e.what() << "; render --backend cpu draws without it\n";
      return kExitNoVulkan;
    }
    std::cerr << "twinraster: no usable Vulkan device: " << e.what()
              << "\n  (render --backend cpu works without one)\n";
    return kExitNoVulkan;
  } catch (const std::exception& e) {
    std::cerr << "twinraster: internal error: " << e.what() << "\n";
    return kExitInternalError;
  }
}
