#include "cpu/fragment_ops.hpp"

#include <algorithm>
#include <cmath>

namespace twinraster::cpu {

namespace {

// Written so that the compiler can vectorize it (no branches, every store unconditional). On x86-64
// a second copy is built for CPUs with AVX2 and FMA, where the fmaf is one instruction; the
// portable copy's fmaf is just as exact, only slower.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
__attribute__((target_clones("arch=haswell", "default")))
#endif
void ShadeRow(float* depth, std::uint32_t* colour, int begin, int end, float py, float a0, float dzdx,
              float dzdy, std::uint32_t fill) {
  for (int px = begin; px < end; ++px) {
    float z = std::fma(dzdy, py, std::fma(dzdx, static_cast<float>(px), a0));
    z = std::min(std::max(z, 0.0f), 1.0f);
    const float stored = depth[px];
    const bool pass = z < stored;  // DepthTestLess
    depth[px] = pass ? z : stored;
    colour[px] = pass ? fill : colour[px];
  }
}

}  // namespace

bool ShadeFragment(Framebuffer& fb, int px, int py, const DepthPlane& plane, std::uint32_t colour) {
  const std::size_t i = std::size_t(py) * fb.width + std::size_t(px);
  const float z = DepthAt(plane, px, py);
  if (!DepthTestLess(z, fb.depth[i])) return false;
  fb.depth[i] = z;
  fb.colour[i] = colour;
  return true;
}

void ShadeSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, std::uint32_t colour) {
  const std::size_t row = std::size_t(py) * fb.width;
  ShadeRow(fb.depth.data() + row, fb.colour.data() + row, span.begin, span.end,
           static_cast<float>(py), plane.a0, plane.dzdx, plane.dzdy, colour);
}

}  // namespace twinraster::cpu
