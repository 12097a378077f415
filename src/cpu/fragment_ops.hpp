// Stages 6 and 7 per fragment: depth from the triangle's plane, the depth test (VK_COMPARE_OP_LESS
// against a D32_SFLOAT buffer cleared to 1.0), the depth write, and the colour write of the
// triangle's flat colour as RGBA8 (no blending).
#pragma once

#include "cpu/depth_plane.hpp"
#include "cpu/rasterize.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

struct Framebuffer {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint32_t> colour;  // RGBA8 bytes per pixel, row-major, top row first
  std::vector<float> depth;

  Framebuffer(std::uint32_t w, std::uint32_t h, std::uint32_t clear_colour, float clear_depth = 1.0f)
      : width(w), height(h), colour(std::size_t{w} * h, clear_colour), depth(std::size_t{w} * h, clear_depth) {}
};

inline bool DepthTestLess(float fragment_z, float stored_z) { return fragment_z < stored_z; }

// One fragment: depth test, and on pass depth and colour writes. Returns whether it passed.
bool ShadeFragment(Framebuffer& fb, int px, int py, const DepthPlane& plane, std::uint32_t colour);

// All fragments of a covered span (the same result as ShadeFragment on each, faster).
void ShadeSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, std::uint32_t colour);

}  // namespace twinraster::cpu
