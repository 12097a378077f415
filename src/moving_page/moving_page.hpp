// `explain SCENE --html FILE` as a page that moves: today's chain page (the head, the panels, the
// end), with a hidden section of controls and the twin's picture that the page's script reveals
// once the embedded browser module runs, and the data the script needs: the scene as a scene
// file's text, the rules the native run chose, the module in base64, the script and its style.
// Without JavaScript it reads as the static page. It computes no number of the chain itself: the
// panels come from explain_report, and in the browser from the module.
#pragma once

#include "chain/explanation.hpp"
#include "twin_rules/twin_rules.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace twinraster::moving_page {

// The canvas sizes the page's controls offer, and the page states.
inline constexpr std::uint32_t kMinCanvasSide = 16, kMaxCanvasSide = 2048;

struct MovingPageInput {
  std::string scene_json;                // self_contained_scene.hpp's scene
  std::string scene_name;                // the saved state is <scene_name>-state.json
  twin_rules::TwinRules twin;            // the rules the picture follows, and their name
  std::span<const std::uint8_t> module;  // the browser module (page_module's .wasm), not empty
  std::optional<std::size_t> instance;   // the trace asked for on the command line
  std::optional<std::size_t> vertex;
};

// `explanation` traces every vertex (ExplainVertices::kAll) of the scene `scene_json` describes.
std::string MovingPageHtml(const Explanation& explanation, const MovingPageInput& input);

// `text` safe inside <script type="application/json">: every "<" written as the JSON escape
// \u003c, so that neither "</script" nor "<!--" can appear in it. `text` must be JSON.
std::string JsonForScript(std::string_view text);

}  // namespace twinraster::moving_page
