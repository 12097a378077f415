// Stage 3, the viewport transform (Vulkan spec "Coordinate Transformations"): clip coordinates to
// window coordinates for a viewport (0, 0, W, H) with depth range [0, 1]. lavapipe computes it in
// two ways, and the twin must use the same one for each vertex:
//  - vertices from the vertex shader (JIT code): xw = fmaf(x * oow, scale, translate), or without
//    FMA (RasterRules::fused_multiply_add false) a multiply and an add, each rounded;
//  - vertices created by clipping (plain C):     xw = (x * oow) * scale + translate, no fma.
// Also the pixel rectangle coverage is limited to (framebuffer ∩ viewport rectangle).
#pragma once

#include "cpu/packets.hpp"
#include "cpu/raster_rules.hpp"

#include <glm/vec4.hpp>

#include <cstdint>

namespace twinraster::cpu {

struct WindowPos {
  float x = 0, y = 0, z = 0;
};

// pipe_viewport_state as lavapipe fills it: scale = (W/2, H/2, maxDepth - minDepth),
// translate = (W/2 + x0, H/2 + y0, minDepth). With it travel the rules of the lavapipe the twin
// copies, which decide how every later stage computes in this viewport.
struct ViewportState {
  float scale[3] = {0, 0, 0};
  float translate[3] = {0, 0, 0};
  RasterRules rules;
};

ViewportState MakeViewport(std::uint32_t width, std::uint32_t height, const RasterRules& rules = {});

WindowPos ViewportTransformShader(const ViewportState& vp, const glm::vec4& clip);   // fma (if the rules fuse)
WindowPos ViewportTransformClipped(const ViewportState& vp, const glm::vec4& clip);  // no fma

// Framebuffer ∩ viewport rectangle, the viewport's bounds rounded as llvmpipe does:
// x0i = (int)(x0 + 0.499f), x1i = (int)(2 * scale + x0 - 0.501f), likewise for y.
PixelRect DrawRegion(const ViewportState& vp, std::uint32_t fb_width, std::uint32_t fb_height);

}  // namespace twinraster::cpu
