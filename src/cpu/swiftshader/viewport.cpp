#include "cpu/swiftshader/viewport.hpp"

#include "cpu/platform.hpp"

#include <bit>
#include <cfloat>
#include <cmath>

namespace twinraster::cpu {

namespace {

// SwiftShader's Min: x < y ? x : y (a NaN x gives y).
float Min(float x, float y) { return x < y ? x : y; }

unsigned Outcode(const glm::vec4& c) {
  unsigned code = 0;
  if (c.w < c.x) code |= kClipRight;
  if (c.w < c.y) code |= kClipTop;
  if (c.w < c.z) code |= kClipFar;
  if (!(-c.w <= c.x)) code |= kClipLeft;
  if (!(-c.w <= c.y)) code |= kClipBottom;
  if (!(0.0f <= c.z)) code |= kClipNear;
  if (std::fabs(c.x) <= FLT_MAX && std::fabs(c.y) <= FLT_MAX && std::fabs(c.z) <= FLT_MAX) code |= kClipFinite;
  return code;
}

}  // namespace

SnapViewport MakeSnapViewport(std::uint32_t width, std::uint32_t height) {
  const float half_width = 0.5f * static_cast<float>(width), half_height = 0.5f * static_cast<float>(height);
  const float one = static_cast<float>(kOutlineOne);
  return {.wxf = half_width * one,
          .hxf = half_height * one,
          .x0xf = half_width * one - one / 2,
          .y0xf = half_height * one - one / 2,
          .width = static_cast<int>(width),
          .height = static_cast<int>(height)};
}

SnappedVertex SnapShaderVertex(const glm::vec4& clip, const SnapViewport& vp) {
  SnappedVertex v;
  v.clip = clip;
  float w = clip.w;
  // w = ±0 becomes ±1 by OR-ing in 1.0f's bits, keeping the sign.
  if (w == 0.0f) w = std::bit_cast<float>(std::bit_cast<std::uint32_t>(w) | std::bit_cast<std::uint32_t>(1.0f));
  v.rhw = 1.0f / w;
  constexpr float kLargest = 2147483520.0f;  // the largest float below 2^31
  v.x = RoundHalfEvenToInt(Min(vp.x0xf + (clip.x * v.rhw) * vp.wxf, kLargest));
  v.y = RoundHalfEvenToInt(Min(vp.y0xf + (clip.y * v.rhw) * vp.hxf, kLargest));
  v.z = clip.z * v.rhw;
  v.outcode = Outcode(clip);
  return v;
}

SnappedPoint SnapPolygonVertex(const glm::vec4& clip, const SnapViewport& vp) {
  const float rhw = clip.w != 0.0f ? 1.0f / clip.w : 1.0f;
  return {RoundHalfEvenToInt(vp.x0xf + (clip.x * rhw) * vp.wxf), RoundHalfEvenToInt(vp.y0xf + (clip.y * rhw) * vp.hxf)};
}

}  // namespace twinraster::cpu
