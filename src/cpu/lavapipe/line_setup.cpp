#include "cpu/lavapipe/line_setup.hpp"

#include "cpu/platform.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster::cpu {

namespace {

// llvmpipe's util_iround: half away from zero, the float add happening first (so 0.49999997f +
// 0.5f rounds up to 1); out of range or NaN gives INT32_MIN, as the truncation does.
std::int32_t RoundHalfAway(float f) { return f >= 0.0f ? TruncateToInt(f + 0.5f) : TruncateToInt(f - 0.5f); }

// Mesa 25's util_iround, (int)lrintf(f): half to even; the long's low 32 bits, as the C cast keeps
// them (a NaN or a value out of long's range gives LONG_MIN, so 0).
std::int32_t RoundHalfEven(float f) {
  return static_cast<std::int32_t>(static_cast<std::uint32_t>(static_cast<std::uint64_t>(std::lrintf(f))));
}

}  // namespace

bool SetUpLine(const WindowPos& a, const WindowPos& b, const PixelRect& region, const RasterRules& rules,
               LineSetup& out) {
  const auto snap = rules.lines_round_half_even ? RoundHalfEven : RoundHalfAway;
  const float dx = a.x - b.x, dy = a.y - b.y;
  const float area = dx * dx + dy * dy;  // the squared length; not fused (-ffp-contract=off)
  if (area == 0.0f) return false;
  const float ooa = 1.0f / area;

  // Half the width across the line, in subpixels.
  const float scale = 0.5f / std::sqrt(area);
  const std::int64_t tx = snap(((-dy) * scale) * 256.0f);
  const std::int64_t ty = snap((dx * scale) * 256.0f);
  const std::int64_t x1 = snap((a.x - 0.5f) * 256.0f), y1 = snap((a.y - 0.5f) * 256.0f);
  const std::int64_t x2 = snap((b.x - 0.5f) * 256.0f), y2 = snap((b.y - 0.5f) * 256.0f);
  const std::int64_t x[4] = {x1 - tx, x2 - tx, x2 + tx, x1 + tx};
  const std::int64_t y[4] = {y1 - ty, y2 - ty, y2 + ty, y1 + ty};

  // llvmpipe's box for lines: ceil-based, exactly the pixels whose centres may be inside.
  const std::int64_t min_x = std::min({x[0], x[1], x[2], x[3]}), max_x = std::max({x[0], x[1], x[2], x[3]});
  const std::int64_t min_y = std::min({y[0], y[1], y[2], y[3]}), max_y = std::max({y[0], y[1], y[2], y[3]});
  PixelRect box;
  box.x0 = static_cast<int>(std::max<std::int64_t>(region.x0, (min_x + 255) >> kSubpixelBits));
  box.x1 = static_cast<int>(std::min<std::int64_t>(region.x1, ((max_x + 255) >> kSubpixelBits) - 1));
  box.y0 = static_cast<int>(std::max<std::int64_t>(region.y0, (min_y + 255) >> kSubpixelBits));
  box.y1 = static_cast<int>(std::min<std::int64_t>(region.y1, ((max_y + 255) >> kSubpixelBits) - 1));
  if (box.x0 > box.x1 || box.y0 > box.y1) return false;
  out.bounds = box;

  for (std::size_t i = 0; i < 4; ++i) {
    const std::size_t j = (i + 1) % 4;
    out.edges[i] = MakeEdge(x[i], y[i], x[j], y[j]);
  }

  const float dz = a.z - b.z;
  out.depth.dzdx = (dz * dx) * ooa;
  out.depth.dzdy = (dz * dy) * ooa;
  out.depth.a0 = a.z - (out.depth.dzdx * (a.x - 0.5f) + out.depth.dzdy * (a.y - 0.5f));
  out.depth.fused = rules.fused_multiply_add;
  return true;
}

}  // namespace twinraster::cpu
