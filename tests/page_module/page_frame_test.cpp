// page_module::ComputePageFrame and PageExplainJson natively, as the browser's module runs them:
// the frame's panels are explain --html's, its trace is the vertex explain --json follows, its
// picture is the twin's, and what the page cannot draw is refused with the words the page shows.
#include "page_module/page_frame.hpp"

#include "base/usage_error.hpp"
#include "chain/draw_list.hpp"
#include "chain/explanation.hpp"
#include "cpu/cpu_renderer.hpp"
#include "explain_report/chain_page.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

using namespace twinraster;

namespace {

// explain --json's followed vertex of its first instance: the one asked for (its only vertex),
// else the first inside the clip volume, else vertex 0; as the trace line's JSON has it.
nlohmann::json FollowedInExplainJson(const nlohmann::json& explain, bool vertex_asked) {
  const nlohmann::json& instance = explain.at("instances").at(0);
  const nlohmann::json& vertices = instance.at("vertices");
  nlohmann::json chosen = vertices.at(0);
  if (!vertex_asked) {
    for (const nlohmann::json& v : vertices) {
      if (!v.at("inside_clip_volume").get<bool>()) continue;
      chosen = v;
      break;
    }
  }
  return {{"instance", instance.at("index")}, {"vertex", chosen}};
}

page_module::PageRequest Request(const std::string& text, std::optional<std::size_t> instance,
                                 std::optional<std::size_t> vertex) {
  page_module::PageRequest request;
  request.scene_json = text;
  request.instance = instance;
  request.vertex = vertex;
  return request;
}

}  // namespace

TEST_CASE("A page frame has explain --html's panels and the vertex explain --json follows and the twin's picture",
          "[page_module]") {
  using Trace = std::optional<std::size_t>;
  const auto [file, instance, vertex] = GENERATE(table<const char*, Trace, Trace>({
      {"scenes/cgfs-transforms.json", std::nullopt, std::nullopt},
      {"scenes/cgfs-transforms.json", 1, 3},
      {"scenes/lit-vertex-colours.json", std::nullopt, std::nullopt},
      {"scenes/lit-vertex-colours.json", std::nullopt, 2},
  }));
  CAPTURE(file, instance.value_or(99), vertex.value_or(99));
  const std::string text = test::ReadFile(test::SourcePath(file));
  const page_module::PageRequest request = Request(text, instance, vertex);
  const page_module::PageFrame frame = page_module::ComputePageFrame(request);

  const Scene scene = ParseScene(text, std::string(page_module::kPageSceneName));
  CHECK(frame.panels_html ==
        explain_report::ChainPanelsHtml(Explain(scene, {instance, vertex, ExplainVertices::kAll})));
  const nlohmann::json explain = nlohmann::json::parse(page_module::PageExplainJson(request));
  CHECK(explain.at("scene") == "page");
  CHECK(explain.at("instances").at(0).at("vertices").size() ==
        (vertex ? 1U : scene.models[scene.instances.at(instance.value_or(0)).model].vertices.size()));
  CHECK(nlohmann::json::parse(frame.trace_json) == FollowedInExplainJson(explain, vertex.has_value()));

  cpu::CpuOptions threads;
  threads.threads = 2;  // the page's one thread draws what render's threads draw
  const Image rendered = cpu::RenderOnCpu(BuildDrawList(scene), threads);
  CHECK(frame.picture.width == scene.canvas.width);
  CHECK(frame.picture.rgba == rendered.rgba);
}

TEST_CASE("A page frame refuses a canvas over the page's bound and a vertex the model lacks in explain's words",
          "[page_module]") {
  const std::string text = test::ReadFile(test::SourcePath("scenes/cgfs-transforms.json"));
  page_module::PageRequest request = Request(text, std::nullopt, std::nullopt);
  request.max_canvas = 512;
  CHECK_THROWS_AS(page_module::ComputePageFrame(request), SceneError);
  CHECK_THROWS_WITH(page_module::ComputePageFrame(request),
                    HasSubstring("600 x 600 is larger than this page draws (512 x 512)"));
  CHECK_THROWS_AS(page_module::PageExplainJson(request), SceneError);
  const page_module::PageRequest vertex = Request(text, std::nullopt, 100000);
  CHECK_THROWS_AS(page_module::ComputePageFrame(vertex), UsageError);
  CHECK_THROWS_AS(page_module::PageExplainJson(vertex), UsageError);
}
