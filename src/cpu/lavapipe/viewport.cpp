#include "cpu/lavapipe/viewport.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster::cpu {

ViewportState MakeViewport(std::uint32_t width, std::uint32_t height, const RasterRules& rules) {
  const float x = 0.0f, y = 0.0f, min_depth = 0.0f, max_depth = 1.0f;
  const float half_width = 0.5f * static_cast<float>(width);
  const float half_height = 0.5f * static_cast<float>(height);
  ViewportState vp;
  vp.rules = rules;
  vp.scale[0] = half_width;
  vp.translate[0] = half_width + x;
  vp.scale[1] = half_height;
  vp.translate[1] = half_height + y;
  vp.scale[2] = max_depth - min_depth;  // clip z in [0, w] (Vulkan), so no 0.5 here
  vp.translate[2] = min_depth;
  return vp;
}

WindowPos ViewportTransformShader(const ViewportState& vp, const glm::vec4& clip) {
  const float oow = 1.0f / clip.w;
  if (!vp.rules.fused_multiply_add) return ViewportTransformClipped(vp, clip);  // the same two roundings
  return {std::fma(clip.x * oow, vp.scale[0], vp.translate[0]), std::fma(clip.y * oow, vp.scale[1], vp.translate[1]),
          std::fma(clip.z * oow, vp.scale[2], vp.translate[2])};
}

WindowPos ViewportTransformClipped(const ViewportState& vp, const glm::vec4& clip) {
  const float oow = 1.0f / clip.w;
  return {(clip.x * oow) * vp.scale[0] + vp.translate[0], (clip.y * oow) * vp.scale[1] + vp.translate[1],
          (clip.z * oow) * vp.scale[2] + vp.translate[2]};
}

PixelRect DrawRegion(const ViewportState& vp, std::uint32_t fb_width, std::uint32_t fb_height) {
  const float half_height = std::fabs(vp.scale[1]);
  const float x0 = vp.translate[0] - vp.scale[0];
  const float y0 = vp.translate[1] - half_height;
  PixelRect viewport;
  viewport.x0 = static_cast<int>(x0 + 0.499f);
  viewport.x1 = static_cast<int>(vp.scale[0] * 2.0f + x0 - 0.501f);
  viewport.y0 = static_cast<int>(y0 + 0.499f);
  viewport.y1 = static_cast<int>(half_height * 2.0f + y0 - 0.501f);
  PixelRect region;
  region.x0 = std::max(0, viewport.x0);
  region.y0 = std::max(0, viewport.y0);
  region.x1 = std::min(static_cast<int>(fb_width) - 1, viewport.x1);
  region.y1 = std::min(static_cast<int>(fb_height) - 1, viewport.y1);
  return region;
}

}  // namespace twinraster::cpu
