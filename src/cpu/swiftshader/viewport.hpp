// SwiftShader's stages 2 and 3 for one vertex (Vulkan spec "Coordinate Transformations"): its
// outcode, and its window position snapped to SwiftShader's 4-bit subpixel grid straight from
// clip space, as SwiftShader's vertex routine and set-up compute them (docs/swiftshader-rules.md,
// "Viewport transform and vertex snapping"). No float window coordinate is formed: the half-pixel
// shift and the scale are folded into constants. It does not clip (clipping.hpp) and
// does not compute depth or colour planes (plane.hpp).
#pragma once

#include <glm/vec4.hpp>

#include <cstdint>

namespace twinraster::cpu {

// 1/16 pixel: SwiftShader's subPixelPrecisionBits is 4 in Chromium's build.
constexpr int kOutlineBits = 4;
constexpr std::int32_t kOutlineOne = 1 << kOutlineBits;

// The viewport (0, 0, width, height) as SwiftShader's draw keeps it: W = width/2, H = height/2,
// wxf = 16 W, hxf = 16 H, x0xf = 16 W - 8, y0xf = 16 H - 8. The -8 puts pixel px's centre at 16 px.
struct SnapViewport {
  float wxf = 0, hxf = 0, x0xf = 0, y0xf = 0;
  int width = 0, height = 0;  // the scissor, [0, width) x [0, height)
};
SnapViewport MakeSnapViewport(std::uint32_t width, std::uint32_t height);

// Outcode bits as SwiftShader numbers them. kFinite is set when |x|, |y|, |z| <= FLT_MAX; a NaN
// coordinate sets kLeft, kBottom or kNear.
enum SnapClipBits : unsigned {
  kClipRight = 1u << 0,   // w < x
  kClipTop = 1u << 1,     // w < y
  kClipFar = 1u << 2,     // w < z
  kClipLeft = 1u << 3,    // !(-w <= x)
  kClipBottom = 1u << 4,  // !(-w <= y)
  kClipNear = 1u << 5,    // !(0 <= z)
  kClipFrustum = 63,
  kClipFinite = 1u << 7,
};

// A vertex after SwiftShader's vertex routine.
struct SnappedVertex {
  glm::vec4 clip{0.0f};
  std::int32_t x = 0, y = 0;  // 1/16 pixel from pixel (0, 0)'s centre
  float z = 0;                // z / w, projected depth
  float rhw = 0;              // 1 / w, with w = ±0 taken as ±1
  unsigned outcode = 0;
};

// cvtps2dq(min(x0xf + ((x * rhw) * wxf), 2147483520)): every operation rounded, half to even.
SnappedVertex SnapShaderVertex(const glm::vec4& clip, const SnapViewport& vp);

// A vertex of a clipped polygon, snapped again by the set-up's scalar code: rhw = w != 0 ? 1/w : 1,
// no clamp.
struct SnappedPoint {
  std::int32_t x = 0, y = 0;
};
SnappedPoint SnapPolygonVertex(const glm::vec4& clip, const SnapViewport& vp);

}  // namespace twinraster::cpu
