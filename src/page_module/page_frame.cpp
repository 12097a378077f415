#include "page_module/page_frame.hpp"

#include "chain/draw_list.hpp"
#include "chain/explanation.hpp"
#include "cpu/cpu_renderer.hpp"
#include "explain_report/chain_page.hpp"
#include "explain_report/explain_json.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace twinraster::page_module {

namespace {

// A canvas the caller cannot hold (the browser's module: its pictures must fit a 32-bit memory)
// is refused before anything is drawn.
void CheckCanvas(const Scene& scene, std::uint32_t max_canvas) {
  if (max_canvas == 0 || (scene.canvas.width <= max_canvas && scene.canvas.height <= max_canvas)) return;
  throw SceneError(std::string(kPageSceneName), "canvas",
                   std::to_string(scene.canvas.width) + " x " + std::to_string(scene.canvas.height) +
                       " is larger than this page draws (" + std::to_string(max_canvas) + " x " +
                       std::to_string(max_canvas) + ")");
}

// The request's scene as the page reads it: named kPageSceneName, its canvas within the bound.
Scene PageScene(const PageRequest& request) {
  Scene scene = ParseScene(request.scene_json, std::string(kPageSceneName));
  CheckCanvas(scene, request.max_canvas);
  return scene;
}

}  // namespace

PageFrame ComputePageFrame(const PageRequest& request) {
  const Scene scene = PageScene(request);
  // The panels draw every vertex's edges, as explain --html's do; the trace line follows the
  // vertex explain would (the one asked for, else the first in view).
  const Explanation explanation = Explain(scene, {request.instance, request.vertex, ExplainVertices::kAll});
  PageFrame frame;
  frame.panels_html = explain_report::ChainPanelsHtml(explanation);
  frame.trace_json =
      explanation.instances.empty() ? "null" : explain_report::FollowedVertexJson(explanation.instances.front()).dump();
  frame.draw_list = BuildDrawList(scene);
  frame.picture = DrawPicture(frame.draw_list, request.rules);
  return frame;
}

std::string PageExplainJson(const PageRequest& request) {
  const Scene scene = PageScene(request);
  const ExplainVertices vertices = explain_report::JsonVertices(request.vertex.has_value());
  return explain_report::ExplainJson(Explain(scene, {request.instance, request.vertex, vertices})).dump(2);
}

Image DrawPicture(const DrawList& list, const cpu::RasterRules& rules) {
  cpu::CpuOptions options;
  options.threads = 1;
  options.rules = rules;
  return cpu::RenderOnCpu(list, options);
}

}  // namespace twinraster::page_module
