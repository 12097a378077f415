// Stage 1 for a lit or vertex-coloured mesh: the light at one vertex, computed in float exactly as
// shaders/triangle.vert (LIT) computes it, and the colour output's conversion to UNORM8.
//   world = ((M[0]*p.x + M[1]*p.y) + M[2]*p.z) + M[3]          M: LitInstance::model
//   n     = (N[0]*n.x + N[1]*n.y) + N[2]*n.z, then n / |n|       N: LitInstance::normal
//   I     = ambient, then for each light in order, where n.l > 0:  I + intensity * (n.l / |l|)
//   colour = (k / 255) * min(I, 1) per channel, k the base colour's byte
// with every dot product summed ((x + y) + z) and every operation rounded to float (this library
// is built without contraction; lavapipe's divide and square root are IEEE).
#pragma once

#include "chain/draw_list.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <bit>
#include <cstdint>

namespace twinraster::cpu {

glm::vec3 LightVertex(const DrawLighting& lighting, const LitInstance& instance, const glm::vec3& position,
                      const glm::vec3& normal, Rgb8 base);

// A base colour as the shader reads it, k / 255 per channel (one IEEE divide each): lit, times
// min(I, 1); a vertex colour on an unlit mesh is this itself (triangle.vert's BaseColour).
inline glm::vec3 BaseColour(Rgb8 c) {
  return glm::vec3(static_cast<float>(c.r) / 255.0f, static_cast<float>(c.g) / 255.0f,
                   static_cast<float>(c.b) / 255.0f);
}

// A fragment shader output channel as the UNORM8 colour attachment stores it: clamped to [0, 1]
// (NaN to 0), times 255, rounded half to even. Adding and taking away 1.5 · 2^23 rounds a float
// in [0, 255] to an integer exactly as lrintf does, in a form the compiler can vectorize.
inline std::uint8_t UnormByte(float c) {
  const float clamped = c > 0.0f ? (c < 1.0f ? c : 1.0f) : 0.0f;
  constexpr float kRound = 12582912.0f;  // 1.5 · 2^23
  return static_cast<std::uint8_t>(static_cast<int>((clamped * 255.0f + kRound) - kRound));
}

// The lit colour as the RGBA8 word the framebuffer holds (alpha 255), as PackRgba.
inline std::uint32_t PackUnorm(const glm::vec3& colour) {
  return std::bit_cast<std::uint32_t>(
      std::array<std::uint8_t, 4>{UnormByte(colour.x), UnormByte(colour.y), UnormByte(colour.z), 255});
}

}  // namespace twinraster::cpu
