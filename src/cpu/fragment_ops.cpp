#include "cpu/fragment_ops.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster::cpu {

namespace {

// Written so that the compiler can vectorize it (no branches, every store unconditional). On x86-64
// a second copy is built for CPUs with AVX2 and FMA, where fmaf is one instruction; the portable
// copy's fmaf is just as exact, only slower.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("arch=haswell", "default")))
#endif
void ShadeRow(float* depth, std::uint8_t* rgba, int begin, int end, float py, float a0, float dzdx,
              float dzdy, std::uint32_t fill) {
  for (int px = begin; px < end; ++px) {
    float z = std::fma(dzdy, py, std::fma(dzdx, static_cast<float>(px), a0));  // PlaneDepth
    z = std::min(std::max(z, 0.0f), 1.0f);                                   // DepthAt's clamp
    const float stored = depth[px];
    const bool pass = z < stored;  // DepthTestLess
    depth[px] = pass ? z : stored;
    std::uint32_t old;
    std::memcpy(&old, rgba + 4 * px, 4);
    const std::uint32_t written = pass ? fill : old;
    std::memcpy(rgba + 4 * px, &written, 4);
  }
}

}  // namespace

void ClearRows(Framebuffer& fb, int row_begin, int row_end, std::uint32_t clear_colour, float clear_depth) {
  const std::size_t begin = fb.index(0, row_begin), end = fb.index(0, row_end);
  std::fill(fb.depth.get() + begin, fb.depth.get() + end, clear_depth);
  std::uint8_t* rgba = fb.colour.rgba.data();
  for (std::size_t i = begin; i < end; ++i) std::memcpy(rgba + 4 * i, &clear_colour, 4);
}

bool ShadeFragment(Framebuffer& fb, int px, int py, const DepthPlane& plane, std::uint32_t colour) {
  const std::size_t i = fb.index(px, py);
  const float z = DepthAt(plane, px, py);
  if (!DepthTestLess(z, fb.depth[i])) return false;
  fb.depth[i] = z;
  std::memcpy(fb.colour.rgba.data() + 4 * i, &colour, 4);
  return true;
}

void ShadeSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, std::uint32_t colour) {
  const std::size_t row = fb.index(0, py);
  ShadeRow(fb.depth.get() + row, fb.colour.rgba.data() + 4 * row, span.begin, span.end,
           static_cast<float>(py), plane.a0, plane.dzdx, plane.dzdy, colour);
}

}  // namespace twinraster::cpu
