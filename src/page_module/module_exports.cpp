// The browser module's interface (docs/pages.md): what the moving chain page calls, over
// ComputePageFrame and PageExplainJson. All strings are UTF-8 given as (pointer, size); all integers
// 32-bit. It keeps one state: the rules set, the last frame (panels, trace, picture, draw list) and
// the last explain JSON asked for. It does not parse controls or draw on a canvas (the page's
// JavaScript does) and reads no file.
//
// Imports, all wasi_snapshot_preview1's: clock_time_get, which must succeed (the twin times its
// draw with libc++'s steady_clock, which aborts when the clock fails: the page gives
// performance.now() in nanoseconds); and environ_get, environ_sizes_get, fd_close, fd_seek,
// fd_write and proc_exit, which wasi-libc's environment, stdio and exit name but no export calls
// (the page answers 52, ENOSYS; proc_exit throws). A throw inside any export traps after its
// message is copied into tr_message() (module_runtime.hpp); the page then instantiates the module
// afresh.
#include "cpu/platform.hpp"
#include "page_module/fmaf_check.hpp"
#include "page_module/module_runtime.hpp"
#include "page_module/page_frame.hpp"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>
#include <string_view>

namespace twinraster::page_module {

namespace {

// The largest canvas side the page draws: a 2048 x 2048 picture is 16 MiB of RGBA, which a 32-bit
// memory holds beside the frame buffers; the page states this limit beside its size controls.
constexpr std::uint32_t kMaxCanvas = 2048;

cpu::RasterRules g_rules;  // lavapipe's, Mesa 22.3.6 on x86-64 with AVX2 and FMA, until the page says
PageFrame g_frame;
std::string g_explain_json;  // tr_explain's

// -1 is explain's default (the first instance, every vertex); anything else is an index, which
// ComputePageFrame checks against the scene.
std::optional<std::size_t> Index(std::int32_t value) {
  if (value < 0) return std::nullopt;
  return static_cast<std::size_t>(value);
}

PageRequest Request(const std::uint8_t* scene, std::uint32_t bytes, std::int32_t instance, std::int32_t vertex) {
  PageRequest request;
  request.scene_json = std::string_view(reinterpret_cast<const char*>(scene), bytes);
  request.rules = g_rules;
  request.instance = Index(instance);
  request.vertex = Index(vertex);
  request.max_canvas = kMaxCanvas;
  return request;
}

}  // namespace

}  // namespace twinraster::page_module

using twinraster::page_module::g_explain_json;
using twinraster::page_module::g_frame;
using twinraster::page_module::g_rules;

#define TR_EXPORT(name) extern "C" __attribute__((export_name(#name)))

TR_EXPORT(tr_alloc) std::uint8_t* tr_alloc(std::uint32_t bytes) {
  return static_cast<std::uint8_t*>(std::malloc(bytes == 0 ? 1 : bytes));
}

TR_EXPORT(tr_free) void tr_free(std::uint8_t* p) { std::free(p); }

TR_EXPORT(tr_max_canvas) std::uint32_t tr_max_canvas() { return twinraster::page_module::kMaxCanvas; }

TR_EXPORT(tr_set_rules)
std::int32_t tr_set_rules(std::int32_t rasterizer, std::int32_t flush_denormals, std::int32_t fused_multiply_add,
                          std::int32_t triangles_round_half_away, std::int32_t lines_round_half_even,
                          std::int32_t wireframe_guard_band, std::int32_t wireframe_clip_edges,
                          std::int32_t vector_bits) {
  using twinraster::cpu::Rasterizer;
  twinraster::cpu::RasterRules rules;
  rules.rasterizer = rasterizer == 1 ? Rasterizer::kSwiftShader : Rasterizer::kLavapipe;
  rules.flush_denormals = flush_denormals != 0;
  rules.fused_multiply_add = fused_multiply_add != 0;
  rules.triangles_round_half_away = triangles_round_half_away != 0;
  rules.lines_round_half_even = lines_round_half_even != 0;
  rules.wireframe_guard_band = wireframe_guard_band != 0;
  rules.wireframe_clip_edges = wireframe_clip_edges != 0;
  rules.vector_bits = vector_bits;
  if (!twinraster::cpu::CanFollow(rules)) {
    // WebAssembly has no denormals-as-zero mode, so such rules would be followed only in name.
    twinraster::page_module::SetMessage(
        "these rules flush denormals to zero (SwiftShader's), which WebAssembly cannot: the page keeps the rules "
        "it had");
    return 1;
  }
  g_rules = rules;
  twinraster::page_module::SetMessage("");
  return 0;
}

TR_EXPORT(tr_update)
std::int32_t tr_update(const std::uint8_t* scene, std::uint32_t bytes, std::int32_t instance, std::int32_t vertex) {
  g_frame = twinraster::page_module::ComputePageFrame(twinraster::page_module::Request(scene, bytes, instance, vertex));
  twinraster::page_module::SetMessage("");
  return 0;
}

// explain --json's text for a state, read with tr_explain_json(): asked for apart from tr_update,
// since the page's own line needs only tr_trace().
TR_EXPORT(tr_explain)
std::int32_t tr_explain(const std::uint8_t* scene, std::uint32_t bytes, std::int32_t instance, std::int32_t vertex) {
  g_explain_json =
      twinraster::page_module::PageExplainJson(twinraster::page_module::Request(scene, bytes, instance, vertex));
  twinraster::page_module::SetMessage("");
  return 0;
}

TR_EXPORT(tr_redraw) std::int32_t tr_redraw() {
  g_frame.picture = twinraster::page_module::DrawPicture(g_frame.draw_list, g_rules);
  return 0;
}

TR_EXPORT(tr_panels) const char* tr_panels() { return g_frame.panels_html.data(); }
TR_EXPORT(tr_panels_size) std::uint32_t tr_panels_size() {
  return static_cast<std::uint32_t>(g_frame.panels_html.size());  // size_t is 32 bits in wasm32
}
TR_EXPORT(tr_trace) const char* tr_trace() { return g_frame.trace_json.data(); }
TR_EXPORT(tr_trace_size) std::uint32_t tr_trace_size() { return static_cast<std::uint32_t>(g_frame.trace_json.size()); }
TR_EXPORT(tr_explain_json) const char* tr_explain_json() { return g_explain_json.data(); }
TR_EXPORT(tr_explain_json_size) std::uint32_t tr_explain_json_size() {
  return static_cast<std::uint32_t>(g_explain_json.size());
}
TR_EXPORT(tr_picture) const std::uint8_t* tr_picture() { return g_frame.picture.rgba.data(); }
TR_EXPORT(tr_picture_width) std::uint32_t tr_picture_width() { return g_frame.picture.width; }
TR_EXPORT(tr_picture_height) std::uint32_t tr_picture_height() { return g_frame.picture.height; }
TR_EXPORT(tr_message) const char* tr_message() { return twinraster::page_module::MessageText(); }
TR_EXPORT(tr_message_size) std::uint32_t tr_message_size() { return twinraster::page_module::MessageSize(); }

// The fmaf proof's run in the module (fmaf_check.hpp): the number of mismatching results, and in
// tr_message() "CASES cases, MISMATCHES mismatches, digest HEX", which a test compares with the
// native build's digest.
TR_EXPORT(tr_fmaf_check) std::int32_t tr_fmaf_check(std::uint32_t seed, std::uint32_t random_cases) {
  const twinraster::page_module::FmafCheck check = twinraster::page_module::CheckFmaf(seed, random_cases);
  char line[160];
  const int n = std::snprintf(line, sizeof line, "%u cases, %u mismatches, digest %016llx, first %a %a %a", check.cases,
                              check.mismatches, static_cast<unsigned long long>(check.digest),
                              static_cast<double>(check.first_bad[0]), static_cast<double>(check.first_bad[1]),
                              static_cast<double>(check.first_bad[2]));
  twinraster::page_module::SetMessage(std::string_view(line, static_cast<std::size_t>(std::max(n, 0))));
  return static_cast<std::int32_t>(check.mismatches);
}
