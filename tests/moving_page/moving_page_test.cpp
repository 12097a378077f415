// The moving page's writer: the scene it carries is the file's scene (the same explanation and the
// same picture), with every number and key as written and --size applied; the page fetches no
// other file and no embedded text can end its script element early; the rules it carries are the
// ones asked for; and a SCENE the page cannot carry, or a build without the module, gives today's
// static page and one note line.
#include "moving_page/moving_page.hpp"

#include "chain/draw_list.hpp"
#include "chain/explanation.hpp"
#include "cpu/cpu_renderer.hpp"
#include "explain_report/chain_page.hpp"
#include "explain_report/explain_json.hpp"
#include "markup/markup.hpp"
#include "moving_page/page_assets.hpp"
#include "moving_page/self_contained_scene.hpp"
#include "page_module/module_blob.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <iterator>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

std::string Shipped(const std::string& name) { return test::SourcePath("scenes/" + name).string(); }

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void WriteText(const std::filesystem::path& file, const std::string& text) { std::ofstream(file) << text; }

moving_page::SelfContainedScene Carried(const std::string& file, const SceneChoice& choice = {}) {
  return moving_page::MakeSelfContainedScene(file, LoadSceneOrObj(file, choice), choice);
}

// explain --json's object for every vertex of the first instances, without the scene's name.
nlohmann::json ExplainedWithoutName(const Scene& scene) {
  nlohmann::json json = explain_report::ExplainJson(Explain(scene, {{}, {}, ExplainVertices::kAll}));
  json.erase("scene");
  return json;
}

Image Picture(const Scene& scene) {
  cpu::CpuOptions options;
  options.threads = 1;
  return cpu::RenderOnCpu(BuildDrawList(scene), options);
}

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// The text of <script ... id="ID">...</script> in `page`.
std::string ScriptText(const std::string& page, const std::string& id) {
  const std::size_t open = page.find("id=\"" + id + "\">");
  REQUIRE(open != std::string::npos);
  const std::size_t start = page.find('>', open) + 1;
  return page.substr(start, page.find("</script>", start) - start);
}

moving_page::MovingPageInput Input(const std::string& json, const std::string& rules_name = "lavapipe") {
  static const std::vector<std::uint8_t> kModule = {0x00, 0x61, 0x73, 0x6d, 0x01, 0x00, 0x00, 0x00};
  return {json, "scene", twin_rules::ChooseTwinRulesByName(rules_name, twin_rules::DetectCpuPath()), kModule, {}, {}};
}

}  // namespace

TEST_CASE("The carried scene with OBJ meshes loads to the file's scene: the same chain and picture", "[moving_page]") {
  const std::string file = Shipped("lit-gouraud.json");
  const moving_page::SelfContainedScene carried = Carried(file);
  REQUIRE(carried.why_not.empty());
  CHECK_THAT(carried.json, HasSubstring("\"obj\": \"data:model/obj;base64,"));
  CHECK(carried.json.find("meshes/") == std::string::npos);  // no path left to a sibling file
  const Scene from_page = ParseScene(carried.json, "page");
  const Scene from_file = LoadScene(file);
  REQUIRE(from_page.models.size() == from_file.models.size());
  for (std::size_t m = 0; m < from_file.models.size(); ++m) {
    INFO("model " << from_file.models[m].name);
    CHECK(from_page.models[m].vertices == from_file.models[m].vertices);
    CHECK(from_page.models[m].normals == from_file.models[m].normals);
    CHECK(from_page.models[m].triangles.size() == from_file.models[m].triangles.size());
  }
  CHECK(ExplainedWithoutName(from_page) == ExplainedWithoutName(from_file));
  CHECK(Picture(from_page).rgba == Picture(from_file).rgba);
}

TEST_CASE("The carried scene keeps the file's keys in order and its numbers exactly", "[moving_page]") {
  const std::string file = Shipped("catlike-grid.json");
  const moving_page::SelfContainedScene carried = Carried(file);
  REQUIRE(carried.why_not.empty());
  const nlohmann::ordered_json written = nlohmann::ordered_json::parse(ReadText(file));
  const nlohmann::ordered_json kept = nlohmann::ordered_json::parse(carried.json);
  CHECK(kept == written);  // ordered: the same keys in the same order, the same doubles
  CHECK_THAT(carried.json, HasSubstring("1.539600717839002"));
  CHECK(ExplainedWithoutName(ParseScene(carried.json, "page")) == ExplainedWithoutName(LoadScene(file)));
}

TEST_CASE("The carried scene has --size applied as explain and render apply it", "[moving_page]") {
  const std::string file = Shipped("cgfs-transforms.json");
  const SceneChoice choice{{}, {}, CanvasSize{320, 200}};
  const moving_page::SelfContainedScene carried = Carried(file, choice);
  REQUIRE(carried.why_not.empty());
  const Scene from_page = ParseScene(carried.json, "page");
  const Scene resized = LoadSceneOrObj(file, choice);
  CHECK(from_page.canvas.width == 320);
  CHECK(from_page.canvas.height == 200);
  CHECK(from_page.viewport.width == resized.viewport.width);
  CHECK(from_page.viewport.height == resized.viewport.height);
  CHECK(Picture(from_page).rgba == Picture(resized).rgba);
}

TEST_CASE("A SCENE the page cannot carry says why in one line", "[moving_page]") {
  const test::TempDir dir;
  WriteText(dir / "with-gltf.json", R"({"canvas": {"width": 8, "height": 8}, "viewport": {"width": 1, "height": 1,
    "distance": 1}, "camera": {"position": [0, 0, 0]}, "models": {"box": {"gltf": "box.gltf"}},
    "instances": [{"model": "box"}]})");
  const Scene any = LoadScene(Shipped("cgfs-transforms.json"));
  const struct {
    std::string argument, why;
  } cases[] = {{"-", "standard input"},
               {Shipped("meshes/sphere.obj"), "an OBJ file on its own"},
               {"model.GLB", "a glTF file"},
               {(dir / "with-gltf.json").string(), "model \"box\" is read from a glTF file"}};
  for (const auto& c : cases) {
    INFO(c.argument);
    const moving_page::SelfContainedScene carried = moving_page::MakeSelfContainedScene(c.argument, any, {});
    CHECK(carried.json.empty());
    CHECK_THAT(carried.why_not, HasSubstring(c.why));
    CHECK(carried.why_not.find('\n') == std::string::npos);
  }
}

TEST_CASE("The page is the static page's head and panels with everything it needs inside it", "[moving_page]") {
  const std::string file = Shipped("cgfs-transforms.json");
  const Scene scene = LoadScene(file);
  const Explanation e = Explain(scene, {{}, {}, ExplainVertices::kAll});
  const std::string page = moving_page::MovingPageHtml(e, Input(Carried(file).json));
  CHECK(page.rfind(explain_report::ChainPageHead(e), 0) == 0);
  CHECK_THAT(page, HasSubstring("<div id=\"twinraster-panels\">\n" + explain_report::ChainPanelsHtml(e) + "</div>"));
  CHECK(page.size() >= markup::kPageEnd.size());
  CHECK(page.substr(page.size() - markup::kPageEnd.size()) == markup::kPageEnd);
  CHECK_THAT(page, HasSubstring("<section id=\"twinraster-moving\" hidden>"));  // nothing shows without JS
  CHECK_THAT(page, HasSubstring(std::string(moving_page::ChainPageScript())));
  // No file beside the page is asked for: no src= attribute, no fetch, no link to a sibling.
  CHECK(page.find("src=") == std::string::npos);
  CHECK(page.find("fetch(") == std::string::npos);
  CHECK(page.find("<link") == std::string::npos);
  CHECK(ScriptText(page, "twinraster-module") == "AGFzbQEAAAA=");  // "\0asm", version 1
  CHECK(Count(page, "</script") == 4);                             // the scene, the page's data, the module, the script
  const nlohmann::json data = nlohmann::json::parse(ScriptText(page, "twinraster-page"));
  CHECK(data["vertex_counts"]["cube"] == 8);
  CHECK(data["instance"] == -1);
  CHECK(data["rules"]["arguments"].size() == 8);
}

TEST_CASE("No text from the scene can end the page's script elements or open a comment in them", "[moving_page]") {
  const test::TempDir dir;
  std::string text = ReadText(Shipped("cgfs-transforms.json"));
  const std::string hostile = "</script><!--<script>alert(1)</SCRIPT>";
  text.replace(text.find("Computer Graphics"), 0, hostile);
  WriteText(dir / "hostile.json", text);
  const std::string file = (dir / "hostile.json").string();
  const Scene scene = LoadScene(file);
  const std::string page =
      moving_page::MovingPageHtml(Explain(scene, {{}, {}, ExplainVertices::kAll}), Input(Carried(file).json));
  const std::string scene_text = ScriptText(page, "twinraster-scene");
  CHECK(scene_text.find('<') == std::string::npos);
  CHECK(Count(page, "</script") == 4);
  const nlohmann::json read_back = nlohmann::json::parse(scene_text);
  CHECK_THAT(read_back["comment"].get<std::string>(), HasSubstring(hostile));
  CHECK(moving_page::JsonForScript("\"a</b\"") == "\"a\\u003c/b\"");
}

TEST_CASE("The page carries the rules asked for, SwiftShader's flushing of denormals included", "[moving_page]") {
  const Scene scene = LoadScene(Shipped("cgfs-transforms.json"));
  const Explanation e = Explain(scene, {{}, {}, ExplainVertices::kAll});
  const std::string page = moving_page::MovingPageHtml(e, Input("{}", "swiftshader"));
  const nlohmann::json rules = nlohmann::json::parse(ScriptText(page, "twinraster-page"))["rules"];
  CHECK(rules["arguments"][0] == 1);  // cpu::Rasterizer::kSwiftShader
  CHECK(rules["arguments"][1] == 1);  // flush_denormals
  CHECK_THAT(rules["text"].get<std::string>(), HasSubstring("SwiftShader"));
  CHECK_THAT(page, HasSubstring("twin: " + markup::Escape(rules["text"].get<std::string>())));
}

TEST_CASE("explain --html writes today's static page and one note line where the page cannot move",
          "[moving_page][cli]") {
  const test::TempDir dir;
  const std::string obj = Shipped("meshes/torus.obj");
  const test::CliResult r = test::RunCli({"explain", obj, "--html", (dir / "torus.html").string()});
  INFO(r.err);
  CHECK(r.exit_code == 0);
  // A build without the module says that first: no page of it moves.
  const std::string why = page_module::ModuleBytes().empty()
                              ? std::string(page_module::ModuleMissingReason())
                              : "SCENE is an OBJ file on its own, not a scene file naming it";
  CHECK(r.err == "note: the page does not move: " + why + "\n");
  const Scene scene = LoadSceneOrObj(obj);
  CHECK(ReadText(dir / "torus.html") == explain_report::ChainPageHtml(Explain(scene, {{}, {}, ExplainVertices::kAll})));
}

TEST_CASE("explain --html writes the moving page when the build has the module, else says why not",
          "[moving_page][cli]") {
  const test::TempDir dir;
  const std::string file = Shipped("cgfs-transforms.json");
  const test::CliResult r = test::RunCli({"explain", file, "--html", (dir / "page.html").string()});
  CHECK(r.exit_code == 0);
  const std::string page = ReadText(dir / "page.html");
  if (page_module::ModuleBytes().empty()) {
    CHECK(r.err == "note: the page does not move: " + std::string(page_module::ModuleMissingReason()) + "\n");
    CHECK(page == explain_report::ChainPageHtml(Explain(LoadScene(file), {{}, {}, ExplainVertices::kAll})));
  } else {
    CHECK(r.err.empty());
    CHECK(ScriptText(page, "twinraster-module") == moving_page::Base64(page_module::ModuleBytes()));
    CHECK(page.size() <= 1'000'000);  // the chapter scene's page: aim at 1 MB or less
  }
}

TEST_CASE("explain --device chooses the page's rules as render does and is refused without --html",
          "[moving_page][cli]") {
  const test::TempDir dir;
  const std::string file = Shipped("cgfs-transforms.json");
  const std::string out = (dir / "page.html").string();
  const test::CliResult alone = test::RunCli({"explain", file, "--device", "swiftshader"});
  CHECK(alone.exit_code == 2);
  CHECK_THAT(alone.err, HasSubstring("--device chooses the page's picture rules: give it with --html"));
  const test::CliResult unknown = test::RunCli({"explain", file, "--html", out, "--device", "no-such-gpu"});
  CHECK(unknown.exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(out));
  const test::CliResult swiftshader = test::RunCli({"explain", file, "--html", out, "--device", "swiftshader"});
  CHECK(swiftshader.exit_code == 0);
  if (!page_module::ModuleBytes().empty()) {
    const nlohmann::json rules = nlohmann::json::parse(ScriptText(ReadText(out), "twinraster-page"))["rules"];
    CHECK(rules["arguments"][1] == 1);  // flush_denormals: the page says it cannot draw them
  }
}

TEST_CASE("A model already carried as a data: URI stays as the scene writes it", "[moving_page]") {
  const test::TempDir dir;
  const moving_page::SelfContainedScene first = Carried(Shipped("lit-gouraud.json"));
  WriteText(dir / "carried.json", first.json);
  const moving_page::SelfContainedScene again = Carried((dir / "carried.json").string());
  REQUIRE(again.why_not.empty());
  CHECK(again.json == first.json);
}
