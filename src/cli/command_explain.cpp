// `twinraster explain SCENE`: prints the chapter's chain for a scene, as text or JSON.
#include "cli/command_line.hpp"
#include "cli/commands.hpp"
#include "chain/explain.hpp"
#include "scene/scene_loader.hpp"

#include <nlohmann/json.hpp>

#include <iostream>

namespace twinraster {

int ExplainCommand(const std::vector<std::string>& args) {
  const CommandLine cl(args, {"--json"}, {"--instance", "--vertex"});
  cl.ExpectPositional({"SCENE"});
  const Scene scene = LoadScene(cl.Positional()[0]);
  const ExplainOptions options{cl.Index("--instance"), cl.Index("--vertex")};
  if (cl.Flag("--json")) {
    std::cout << ExplainJson(scene, options).dump(2) << "\n";
  } else {
    std::cout << ExplainText(scene, options);
  }
  return kExitOk;
}

}  // namespace twinraster
