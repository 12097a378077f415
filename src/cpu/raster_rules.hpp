// Which Vulkan the CPU twin copies: whose set-up and coverage (lavapipe's or SwiftShader's), and
// for lavapipe the few operations whose arithmetic differs between Mesa releases and between the
// CPU paths Mesa's JIT takes (docs/lavapipe-paths.md and docs/swiftshader-rules.md say which, with
// the source's file and line). The defaults are Mesa 22.3.6 on an x86-64 CPU with AVX2 and FMA.
// It does not say which device a rule row was proven on: twin_rules/twin_rules.hpp does.
#pragma once

#include <cstdint>

namespace twinraster::cpu {

// The two rasterizers the twin copies. They share the vertex stage, lighting, the bands, the depth
// test and the colour write; they part at clipping, snapping, coverage and the interpolation planes.
enum class Rasterizer : std::uint8_t {
  kLavapipe,     // Mesa's llvmpipe: 8 subpixel bits, edge functions, planes at pixel (0, 0)
  kSwiftShader,  // SwiftShader (Subzero, Chromium's build): 4 subpixel bits, outlines, anchored planes
};

struct RasterRules {
  Rasterizer rasterizer = Rasterizer::kLavapipe;
  // Denormal inputs read as 0 and denormal results become 0 (MXCSR DAZ and FTZ), as in the
  // threads where SwiftShader runs every shader and its set-up.
  bool flush_denormals = false;
  // The JIT fuses a * b + c into one rounding (LLVM's fmuladd where Mesa enables FMA): the
  // viewport transform of shader vertices and the per-pixel depth plane. Without FMA (Mesa's
  // sse4.1 path, or a CPU without it): a multiply, then an add, each rounded.
  bool fused_multiply_add = true;
  // Triangle vertices snap to 1/256 pixel half to even (cvtps2dq on x86-64), or, where Mesa 22.3.6
  // is built without SSE (aarch64), by util_iround's C form: half away from zero.
  bool triangles_round_half_away = false;
  // Line endpoints snap to 1/256 pixel by util_iround: half away from zero in Mesa 22.3.6 on
  // x86-64, lrintf (half to even) from Mesa 25.
  bool lines_round_half_even = false;
  // Polygon mode LINE clips x and y at the guard band |x|, |y| <= 2w (Mesa 25: lines and points
  // take draw's guard band), not at the view volume's |x|, |y| <= w as filled triangles do.
  bool wireframe_guard_band = false;
  // Polygon mode LINE also draws the edges clipping makes along a clip plane. No driver the twin
  // copies does (lavapipe clears their edge flags); Polygon Mode read strictly would, so the
  // verifier's tests draw it as a conformant variant.
  bool wireframe_clip_edges = false;
  // lavapipe's native vector width in bits (LP_NATIVE_VECTOR_WIDTH; 256 with AVX, else 128).
  int vector_bits = 256;

  bool operator==(const RasterRules&) const = default;
};

// subPixelPrecisionBits of the device these rules copy.
constexpr int SubpixelBitsOf(const RasterRules& rules) { return rules.rasterizer == Rasterizer::kSwiftShader ? 4 : 8; }

}  // namespace twinraster::cpu
