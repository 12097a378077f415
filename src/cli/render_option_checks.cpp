#include "cli/render_option_checks.hpp"

#include "base/usage_error.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "twin_rules/lavapipe_path.hpp"
#include "twin_rules/twin_rules.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <set>
#include <string>

namespace twinraster::cli {

void ResolveOptions(RenderArguments& a) {
  a.run.backends = a.backend == "gpu"   ? run::Backends::kGpu
                   : a.backend == "cpu" ? run::Backends::kCpu
                                        : run::Backends::kBoth;
  a.run.rules = a.rules == "book" ? run::Rules::kBook : run::Rules::kVulkan;
  a.run.verify = a.verify;
  a.run.threads = a.threads;
  a.run.device = a.device;
  if (a.run.rules != run::Rules::kBook) {
    // A device asked for decides the twin's rules; with no device to open, its name must say which.
    if (a.run.backends == run::Backends::kCpu && !a.device.empty())
      twin_rules::ChooseTwinRulesByName(a.device, twin_rules::DetectCpuPath());
    return;
  }
  if (a.verify)
    throw UsageError("--verify judges by Vulkan's rules, and --rules book draws by the demos': drop one of them");
  if (!a.device.empty())
    throw UsageError("--device chooses Vulkan's rules, and --rules book draws by the demos': drop one of them");
  if (a.backend_given && a.run.backends != run::Backends::kCpu) {
    throw UsageError("--rules book draws on the CPU only, as the chapter's demos do: drop --backend " + a.backend);
  }
  a.run.backends = run::Backends::kCpu;
}

namespace {

// A name that ends in .png (in any case) and so looks like one file, not a directory of several.
bool LooksLikePng(const std::string& name) {
  std::string end = name.size() > 4 ? name.substr(name.size() - 4) : "";
  std::transform(end.begin(), end.end(), end.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return end == ".png";
}

// Several scenes: -o is a directory (default .), and each scene's files are named after it.
void CheckSeveralScenes(RenderArguments& a) {
  std::set<std::string> names;
  for (const std::string& scene : a.scenes) {
    if (IsStandardStream(scene)) throw UsageError("SCENE - (standard input) can only be rendered on its own");
    const std::string name = std::filesystem::path(scene).stem().string();
    if (!names.insert(name).second) {
      throw UsageError("two scenes are named \"" + name +
                       "\": their images would overwrite each other; render them "
                       "in separate calls");
    }
  }
  if (a.output && IsStandardStream(*a.output))
    throw UsageError("-o -: several scenes make several PNGs; give a directory");
  std::error_code ignored;
  if (a.output && std::filesystem::exists(*a.output, ignored) && !std::filesystem::is_directory(*a.output, ignored)) {
    throw UsageError("-o " + *a.output + ": with several scenes, -o names a directory, and this is a file");
  }
  // multi.png would become a directory of PNGs: almost surely a slip for one scene's file name.
  if (a.output && !NamesDirectory(*a.output) && LooksLikePng(*a.output)) {
    throw UsageError("-o " + *a.output + ": several scenes are written into a directory, and this names a PNG; give " +
                     "a directory (-o " + a.output->substr(0, a.output->size() - 4) + "/), or " + *a.output +
                     "/ for a directory of that name");
  }
  a.directory = a.output.value_or(".");
}

}  // namespace

// Every check on the arguments that needs no scene and no device, so that a mistake costs nothing.
void CheckOutput(RenderArguments& a) {
  if (a.report && IsStandardStream(*a.report))
    throw UsageError("--report -: the report is a directory (index.html and thumbs/); give a directory");
  if (a.junit && IsStandardStream(*a.junit)) {
    if (a.json) throw UsageError("--junit - and --json both want standard output: drop one of them");
    if (a.output && IsStandardStream(*a.output))
      throw UsageError("--junit - and -o - both want standard output: give one of them a file");
  }
  if (a.scenes.size() > 1) return CheckSeveralScenes(a);
  const std::string& scene = a.scenes.front();
  if (IsStandardStream(scene) && !a.output) {
    throw UsageError("SCENE - (standard input) needs -o OUT.png, or -o - for the PNG on standard output");
  }
  if (!a.output || !IsStandardStream(*a.output)) {
    // -o DIR/ or an existing directory: the scene's files go there, named after it, as in a batch.
    if (a.output && NamesDirectory(*a.output)) {
      if (IsStandardStream(scene))
        throw UsageError("-o " + *a.output + ": SCENE - (standard input) has no name for its files; give -o OUT.png");
      a.directory = *a.output;
    } else if (a.output) {
      ExpectPngName("-o", *a.output);
    }
    return;
  }
  if (a.run.backends == run::Backends::kBoth) {
    throw UsageError(
        "-o - writes one PNG to standard output, and --backend both makes two: add --backend gpu or "
        "--backend cpu, or give -o OUT.png");
  }
  if (a.json) throw UsageError("-o - and --json both want standard output: drop one of them");
  if (a.report) throw UsageError("-o - writes no PNG file for --report's page to show: give -o OUT.png");
  if (StandardOutputIsTerminal()) {
    throw UsageError("-o -: standard output is a terminal; redirect it (> out.png) or pipe it to another program");
  }
}

}  // namespace twinraster::cli
