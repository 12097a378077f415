#include "moving_page/moving_page.hpp"

#include "explain_report/chain_page.hpp"
#include "markup/markup.hpp"
#include "moving_page/page_assets.hpp"
#include "moving_page/self_contained_scene.hpp"

#include <nlohmann/json.hpp>

namespace twinraster::moving_page {

namespace {

// The rules as tr_set_rules takes them, in its argument order, and their name.
nlohmann::ordered_json RulesJson(const twin_rules::TwinRules& twin) {
  const cpu::RasterRules& r = twin.rules;
  return {{"text", twin.text},
          {"exact", twin.exact},
          {"arguments",
           {r.rasterizer == cpu::Rasterizer::kSwiftShader ? 1 : 0, int{r.flush_denormals}, int{r.fused_multiply_add},
            int{r.triangles_round_half_away}, int{r.lines_round_half_even}, int{r.wireframe_guard_band},
            int{r.wireframe_clip_edges}, r.vector_bits}}};
}

// What the script needs besides the scene: the trace asked for (-1: explain's default), each
// model's vertex count and how many instances explain shows untold (the traced vertex's bounds)
// and the canvas sizes offered.
nlohmann::ordered_json PageJson(const Explanation& e, const MovingPageInput& in) {
  nlohmann::ordered_json vertex_counts = nlohmann::ordered_json::object();
  for (const Model& model : e.scene->models) vertex_counts[model.name] = model.vertices.size();
  const auto index = [](const std::optional<std::size_t>& i) { return i ? static_cast<long long>(*i) : -1LL; };
  return {{"name", in.scene_name},
          {"instance", index(in.instance)},
          {"vertex", index(in.vertex)},
          {"vertex_counts", vertex_counts},
          {"canvas_min", kMinCanvasSide},
          {"canvas_max", kMaxCanvasSide},
          {"explained_instances", kExplainedInstances},
          {"rules", RulesJson(in.twin)}};
}

std::string DataScript(std::string_view id, std::string_view type, std::string_view text) {
  return "<script type=\"" + std::string(type) + "\" id=\"" + std::string(id) + "\">" + std::string(text) +
         "</script>\n";
}

// Hidden until the script has the module running: without JavaScript none of it shows. The
// script builds the controls into #twinraster-controls from the scene.
std::string ControlsSection(const MovingPageInput& in) {
  std::string html = "<section id=\"twinraster-moving\" hidden>\n<h2>Move the chain</h2>\n";
  html +=
      "<p>Every number and the picture below are computed by twinraster's own C++ (the loader, the "
      "chain, explain's writers and the CPU twin) compiled to WebAssembly and embedded in this page; "
      "the script only wires the controls and draws. Canvas sides: " +
      std::to_string(kMinCanvasSide) + " to " + std::to_string(kMaxCanvasSide) + " pixels.</p>\n";
  html +=
      "<p class=\"twinraster-actions\"><button type=\"button\" id=\"twinraster-save\">Save scene</button> "
      "<button type=\"button\" id=\"twinraster-reset\">Reset</button></p>\n";
  html += "<p id=\"twinraster-status\" role=\"status\" aria-live=\"polite\"></p>\n";
  html += "<p id=\"twinraster-trace\"></p>\n";
  // The controls beside the picture, so that the picture stays in view while a slider moves.
  html += "<div class=\"twinraster-stage\"><div id=\"twinraster-controls\"></div>\n";
  html +=
      "<figure id=\"twinraster-twin\"><canvas id=\"twinraster-picture\" width=\"1\" height=\"1\"></canvas>"
      "<figcaption>The CPU twin's picture of this state, one thread. twin: " +
      markup::Escape(in.twin.text) + "</figcaption></figure></div>\n</section>\n";
  return html;
}

}  // namespace

std::string JsonForScript(std::string_view text) {
  std::string safe;
  safe.reserve(text.size());
  for (const char c : text) {
    if (c == '<') {
      safe += "\\u003c";  // only inside a string: JSON has no '<' elsewhere
    } else {
      safe += c;
    }
  }
  return safe;
}

std::string MovingPageHtml(const Explanation& e, const MovingPageInput& in) {
  std::string page = explain_report::ChainPageHead(e);
  page += "<style>" + std::string(ChainPageStyle()) + "</style>\n";
  page += ControlsSection(in);
  page += "<div id=\"twinraster-panels\">\n" + explain_report::ChainPanelsHtml(e) + "</div>\n";
  page += DataScript("twinraster-scene", "application/json", JsonForScript(in.scene_json));
  page += DataScript("twinraster-page", "application/json", JsonForScript(PageJson(e, in).dump()));
  page += DataScript("twinraster-module", "application/octet-stream", Base64(in.module));
  page += "<script id=\"twinraster-script\">\n" + std::string(ChainPageScript()) + "</script>\n";
  page += markup::kPageEnd;
  return page;
}

}  // namespace twinraster::moving_page
