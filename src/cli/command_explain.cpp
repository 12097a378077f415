// `twinraster explain SCENE`: prints the chapter's chain for a scene, as text or JSON.
#include "chain/explain.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/parser_setup.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace twinraster {

namespace {

struct ExplainArguments {
  std::string scene;
  std::optional<std::size_t> instance, vertex;
  bool json = false;
};

int Explain(const ExplainArguments& a) {
  const Scene scene = LoadSceneArgument(a.scene);
  const ExplainOptions options{a.instance, a.vertex};
  if (a.json) {
    std::cout << ExplainJson(scene, options).dump(2) << "\n";
  } else {
    std::cout << ExplainText(scene, options);
  }
  return kExitOk;
}

}  // namespace

CommandRun AddExplainCommand(CLI::App& app) {
  auto a = std::make_shared<ExplainArguments>();
  CLI::App* command = AddSubcommand(
      app, "explain", "print a scene's matrices and trace its vertices to the screen",
      "The matrices are row-major with column vectors on the right, as the chapter writes them.\n"
      "Exit codes: 0 done, 2 bad input or usage, 4 internal error.");
  command
      ->add_option("SCENE", a->scene,
                   "the scene file (JSON) or an OBJ mesh (.obj, in the scene render gives it),\n"
                   "or - to read the scene from standard input")
      ->required();
  ExpectIndex(command->add_option("--instance", a->instance, "only instance I (counted from 0)")->type_name("I"));
  ExpectIndex(command->add_option("--vertex", a->vertex, "only vertex V of each instance (counted from 0)")->type_name("V"));
  command->add_flag("--json", a->json, "print one JSON object (twinraster.explain/1, docs/json-output.md)");
  return [a] { return Explain(*a); };
}

}  // namespace twinraster
