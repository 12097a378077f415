// `twinraster explain SCENE`: prints the chapter's chain for a scene, as text or JSON, and with
// --html draws it as a page.
#include "base/usage_error.hpp"
#include "chain/explanation.hpp"
#include "cli/commands.hpp"
#include "cli/io_arguments.hpp"
#include "cli/output_paths.hpp"
#include "cli/parser_setup.hpp"
#include "cli/scene_choice_options.hpp"
#include "explain_report/chain_page.hpp"
#include "explain_report/explain_json.hpp"
#include "explain_report/explain_text.hpp"
#include "files/staged_file.hpp"
#include "moving_page/moving_page.hpp"
#include "moving_page/self_contained_scene.hpp"
#include "page_module/module_blob.hpp"
#include "twin_rules/twin_rules.hpp"

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>

#include <iostream>
#include <memory>

namespace twinraster::cli {

namespace {

struct ExplainArguments {
  std::string scene;
  std::optional<std::size_t> instance, vertex;
  bool all_vertices = false;
  bool json = false;
  std::optional<std::string> html;
  std::string device;           // whose rules the moving page's picture follows; empty: render --backend cpu's
  SceneChoiceArguments choice;  // --camera, --scene, --size
};

// The text traces one vertex per instance unless asked for all; the JSON every vertex unless
// --vertex picks one (explain_report::JsonVertices).
ExplainVertices VerticesFor(const ExplainArguments& a) {
  if (a.all_vertices) return ExplainVertices::kAll;
  return a.json ? explain_report::JsonVertices(a.vertex.has_value()) : ExplainVertices::kTraced;
}

// The page follows one vertex of the first explained instance: without one there is no chain to draw.
void CheckDrawable(const Explanation& e) {
  if (e.instances.empty()) throw UsageError("--html: the scene has no instance to draw");
  const InstanceExplanation& x = e.instances.front();
  if (x.vertices.empty()) {
    throw UsageError("--html: instance " + std::to_string(x.index) + " (model \"" + x.model->name +
                     "\") has no vertex to draw");
  }
}

// The rules `render --backend cpu` would draw by: the device named, or lavapipe's on this machine.
twin_rules::TwinRules PageRules(const ExplainArguments& a) {
  const twin_rules::CpuPath path = twin_rules::DetectCpuPath();
  return a.device.empty() ? twin_rules::ChooseTwinRules({}, path) : twin_rules::ChooseTwinRulesByName(a.device, path);
}

// The page that moves when it can; else today's static page, and one line on standard error
// saying why it does not move.
std::string PageHtml(const ExplainArguments& a, const Scene& scene, const Explanation& chain,
                     const twin_rules::TwinRules& rules) {
  std::string why_not(page_module::ModuleMissingReason());
  moving_page::SelfContainedScene carried;
  if (page_module::ModuleBytes().empty()) {
    if (why_not.empty()) why_not = "this build has no browser module";
  } else {
    carried = moving_page::MakeSelfContainedScene(a.scene, scene, ChoiceOf(a.choice));
    why_not = carried.why_not;
  }
  if (!why_not.empty()) {
    std::cerr << "note: the page does not move: " << why_not << "\n";
    return explain_report::ChainPageHtml(chain);
  }
  return moving_page::MovingPageHtml(
      chain, {carried.json, scene.name, rules, page_module::ModuleBytes(), a.instance, a.vertex});
}

int RunExplain(const ExplainArguments& a) {
  if (a.all_vertices && a.vertex) {
    throw UsageError("--all-vertices traces every vertex, --vertex V traces one: give one of them");
  }
  const bool page_to_stdout = a.html && IsStandardStream(*a.html);
  if (page_to_stdout && a.json) throw UsageError("--html - and --json both want standard output: drop one of them");
  if (!a.device.empty() && !a.html) throw UsageError("--device chooses the page's picture rules: give it with --html");
  const std::optional<twin_rules::TwinRules> rules = a.html ? std::optional(PageRules(a)) : std::nullopt;
  if (a.html && !page_to_stdout) {
    OutputPaths paths;  // before the scene is read: a bad destination costs nothing
    paths.File("--html " + *a.html, *a.html);
    paths.MakeDirectories();
  }
  const Scene scene = LoadSceneArgument(a.scene, ChoiceOf(a.choice));
  PrintSceneNotes(scene, a.scene);
  if (a.html) {
    // The page draws every vertex's edges, and follows the vertex asked for or the first in view.
    // Explain checks --instance and --vertex before the file is written.
    const Explanation page_chain = Explain(scene, {a.instance, a.vertex, ExplainVertices::kAll});
    CheckDrawable(page_chain);
    const std::string html = PageHtml(a, scene, page_chain, *rules);
    if (page_to_stdout) {
      WriteStandardOutput(html);
      return kExitOk;
    }
    files::StagedFile page(*a.html, html);
    page.Commit();
    if (!a.json) {
      std::cout << "wrote " << *a.html << "\n";
      return kExitOk;
    }
  }
  const Explanation explanation = Explain(scene, {a.instance, a.vertex, VerticesFor(a)});
  if (a.json) {
    std::cout << explain_report::ExplainJson(explanation).dump(2) << "\n";
  } else {
    std::cout << explain_report::ExplainText(explanation);
  }
  return kExitOk;
}

}  // namespace

CommandRun AddExplainCommand(CLI::App& app) {
  auto a = std::make_shared<ExplainArguments>();
  CLI::App* command =
      AddSubcommand(app, "explain", "print a scene's matrices and trace its vertices to the screen",
                    "The matrices are row-major with column vectors on the right, as the chapter writes them.\n"
                    "Exit codes: 0 done, 2 bad input or usage, 4 internal error.");
  command
      ->add_option("SCENE", a->scene,
                   "the scene file (JSON), an OBJ mesh (.obj, in the scene render gives it), a glTF\n"
                   "2.0 file (.gltf or .glb), or - to read the scene from standard input")
      ->required();
  ExpectIndex(command->add_option("--instance", a->instance, "only instance I (counted from 0)")->type_name("I"));
  ExpectIndex(command
                  ->add_option("--vertex", a->vertex,
                               "trace vertex V of each instance (counted from 0; default: the first\n"
                               "inside the clip volume)")
                  ->type_name("V"));
  command->add_flag("--all-vertices", a->all_vertices,
                    "trace every vertex of each instance (--json does unless --vertex is given)");
  command
      ->add_option("--html", a->html,
                   "draw the chain as a page instead of the text, and print where it went: the\n"
                   "model, the world from above and the side with the camera's frustum, camera\n"
                   "space, NDC and the canvas, each with its matrix and the traced vertex\n"
                   "(--instance, --vertex; default: instance 0's first vertex in view); - writes\n"
                   "the page to standard output. The page moves: its controls change the scene and\n"
                   "the embedded module recomputes every panel and the twin's picture; where it\n"
                   "cannot (no module in this build, an OBJ or glTF file on its own, a glTF model,\n"
                   "a scene on standard input) the page is static and a note says why")
      ->type_name("FILE");
  command
      ->add_option("--device", a->device,
                   "with --html: the device whose rules the page's picture follows, by name as\n"
                   "render takes it (lavapipe, swiftshader); default: lavapipe's on this machine,\n"
                   "as render --backend cpu draws")
      ->type_name("NAME");
  AddSceneChoiceOptions(*command, a->choice);
  command->add_flag("--json", a->json,
                    "print one JSON object (twinraster.explain/3, docs/json-output.md), also\n"
                    "with --html");
  return [a] { return RunExplain(*a); };
}

}  // namespace twinraster::cli
