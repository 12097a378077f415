// The small right triangle the SwiftShader set-up and coverage tests draw, and a snapped vertex
// made by hand; shared by setup_test.cpp and coverage_test.cpp. It tests nothing itself.
#pragma once

#include "cpu/swiftshader/viewport.hpp"

#include <glm/vec4.hpp>

#include <array>
#include <cstdint>

namespace twinraster::cpu::test {

// Pixel centres (0, 0), (4, 0) and (0, 4), in 4-bit subpixels: the pixels px, py >= 0 with
// px + py < 4 are inside; the hypotenuse, a right and bottom edge, passes through the centres with
// px + py = 4 exactly.
inline constexpr std::array<SnappedPoint, 3> kCorner = {{{0, 0}, {64, 0}, {0, 64}}};

inline SnappedVertex Vertex(std::int32_t x, std::int32_t y, float w = 1.0f) {
  SnappedVertex v;
  v.x = x;
  v.y = y;
  v.clip = glm::vec4(0, 0, 0, w);
  return v;
}

}  // namespace twinraster::cpu::test
