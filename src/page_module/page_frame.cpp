#include "page_module/page_frame.hpp"

#include "chain/draw_list.hpp"
#include "chain/explanation.hpp"
#include "cpu/cpu_renderer.hpp"
#include "explain_report/chain_page.hpp"
#include "explain_report/explain_json.hpp"
#include "scene/scene_loader.hpp"

#include <nlohmann/json.hpp>

namespace twinraster::page_module {

PageFrame ComputePageFrame(const PageRequest& request) {
  const Scene scene = ParseScene(request.scene_json, std::string(kPageSceneName));
  PageFrame frame;
  // The panels draw every vertex's edges; the numbers trace every vertex unless one is asked for,
  // as explain --html and explain --json do.
  frame.panels_html =
      explain_report::ChainPanelsHtml(Explain(scene, {request.instance, request.vertex, ExplainVertices::kAll}));
  const ExplainVertices json_vertices = request.vertex ? ExplainVertices::kTraced : ExplainVertices::kAll;
  frame.explain_json =
      explain_report::ExplainJson(Explain(scene, {request.instance, request.vertex, json_vertices})).dump(2);
  cpu::CpuOptions options;
  options.threads = 1;
  options.rules = request.rules;
  frame.picture = cpu::RenderOnCpu(BuildDrawList(scene), options);
  return frame;
}

}  // namespace twinraster::page_module
