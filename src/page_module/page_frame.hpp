// One state of the moving chain page, computed: a scene file's text in; the chain's panels, the
// traced vertex's numbers and the twin's picture out (and, when asked, what `explain --json`
// prints). The browser's module runs exactly this (module_exports.cpp), and the native build runs
// it too, so that tests can hold the two to the same bits. It reads no file (a scene's meshes come
// as data: URIs), starts no thread, and chooses no rules: the page carries the rules the native
// run chose.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/raster_rules.hpp"
#include "image/image.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace twinraster::page_module {

struct PageRequest {
  std::string_view scene_json;          // a scene file, as `twinraster render` reads it
  cpu::RasterRules rules;               // whose arithmetic the picture copies
  std::optional<std::size_t> instance;  // the traced instance (explain --instance)
  std::optional<std::size_t> vertex;    // the traced vertex (explain --vertex)
  std::uint32_t max_canvas = 0;         // the largest canvas side the caller draws (0: any)
};

struct PageFrame {
  std::string panels_html;  // explain_report::ChainPanelsHtml: the page's figures
  std::string trace_json;   // the first shown instance's followed vertex (FollowedVertexJson), or null
  Image picture;            // the twin's image on one thread, as render --backend cpu draws it
  DrawList draw_list;       // what the picture was drawn from, for drawing it again (DrawPicture)
};

// The name a scene read from the page takes in messages and in Scene::name.
inline constexpr std::string_view kPageSceneName = "page";

// Throws the loader's SceneError for a scene it refuses, and UsageError for an instance or vertex
// the scene does not have, with explain's words; SceneError for a canvas larger than max_canvas.
PageFrame ComputePageFrame(const PageRequest& request);

// explain --json's object for the request, as the command prints it (--instance and --vertex as
// the request's). Apart from the frame: only tests and scripts ask for it, and a lit mesh's is
// megabytes (lit-gouraud's 8.3 MB), which every change of the page would write and parse.
std::string PageExplainJson(const PageRequest& request);

// The twin's picture of a draw list, on one thread: the page's picture, and nothing else.
Image DrawPicture(const DrawList& list, const cpu::RasterRules& rules);

}  // namespace twinraster::page_module
