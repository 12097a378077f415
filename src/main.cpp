// twinraster's command line: explain a scene's transform chain (and, later, render and compare).
#include "command_line.hpp"
#include "explain.hpp"
#include "scene_loader.hpp"
#include "usage_error.hpp"

#include <nlohmann/json.hpp>

#include <exception>
#include <iostream>
#include <string>
#include <vector>

namespace {

using namespace twinraster;

constexpr const char* kUsage =
    "usage:\n"
    "  twinraster explain SCENE [--instance I] [--vertex V] [--json]\n"
    "      print the chapter's matrix chain for SCENE and trace its vertices to the framebuffer\n";

int Explain(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--json"}, {"--instance", "--vertex"});
  cl.ExpectPositional({"SCENE"});
  const Scene scene = LoadScene(cl.Positional()[0]);
  const ExplainOptions options{cl.Index("--instance"), cl.Index("--vertex")};
  if (cl.Flag("--json")) {
    std::cout << ExplainJson(scene, options).dump(2) << "\n";
  } else {
    std::cout << ExplainText(scene, options);
  }
  return 0;
}

int Run(const std::vector<std::string>& args) {
  if (args.empty()) throw UsageError("missing command");
  const std::string& command = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (command == "explain") return Explain(rest);
  if (command == "help" || command == "--help" || command == "-h") {
    std::cout << kUsage;
    return 0;
  }
  throw UsageError("unknown command \"" + command + "\"");
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return Run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const SceneError& e) {
    std::cerr << "twinraster: " << e.what() << "\n";
    return 2;
  } catch (const UsageError& e) {
    std::cerr << "twinraster: " << e.what() << "\n" << kUsage;
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "twinraster: internal error: " << e.what() << "\n";
    return 4;
  }
}
