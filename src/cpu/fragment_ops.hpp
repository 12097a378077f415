// Stages 6 and 7 per fragment: depth from the primitive's plane (lavapipe's DepthPlane or
// SwiftShader's AnchoredPlane), the depth test against a
// D32_SFLOAT buffer (VK_COMPARE_OP_LESS and cleared to 1.0, or with reversed Z
// VK_COMPARE_OP_GREATER and cleared to 0.0), the depth write, and the colour write of the
// triangle's flat colour, or its interpolated Gouraud colour, as RGBA8 (no blending). The colour attachment is the
// output Image itself.
#pragma once

#include "cpu/lavapipe/plane.hpp"
#include "cpu/lavapipe/planes.hpp"
#include "cpu/packets.hpp"
#include "cpu/swiftshader/plane.hpp"
#include "image/frame_memory.hpp"
#include "image/image.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>

namespace twinraster::cpu {

// Depth memory, reused between renders on the same thread: fresh memory costs a page fault per
// 4 KiB, which for a simple scene is as much as drawing it.
class DepthBuffer {
 public:
  explicit DepthBuffer(std::size_t size);  // not cleared
  ~DepthBuffer();                          // hands the memory back for the next render
  DepthBuffer(DepthBuffer&& other) noexcept;
  DepthBuffer& operator=(DepthBuffer&&) = delete;
  DepthBuffer(const DepthBuffer&) = delete;
  DepthBuffer& operator=(const DepthBuffer&) = delete;

  float* data() { return data_.data(); }
  const float* data() const { return data_.data(); }
  float& operator[](std::size_t i) { return data_[i]; }
  float operator[](std::size_t i) const { return data_[i]; }

 private:
  FrameVector<float> data_;  // at least the frame's size
};

// The depth test's VkCompareOp. Both are strict: of two fragments at equal depth the first stays.
enum class DepthCompare { kLess, kGreater };

inline bool DepthTest(DepthCompare op, float fragment_z, float stored_z) {
  return op == DepthCompare::kLess ? fragment_z < stored_z : fragment_z > stored_z;
}

// The value depth is cleared to: the far end, which no fragment passes against.
inline float ClearDepth(DepthCompare op) { return op == DepthCompare::kLess ? 1.0f : 0.0f; }

// The colour attachment, whole, and depth as a ring of rows: row py's depth is ring row
// py % depth_rows. A frame drawn band by band, each band whole before the next on its thread,
// needs depth only for the bands being drawn at once, so its ring is that many bands: 38 KB of
// depth, not 1.4 MB of fresh pages, for the chapter's 600x600 on one thread.
struct Framebuffer {
  Image colour;       // RGBA8, top row first
  DepthBuffer depth;  // D32_SFLOAT, depth_rows rows of the frame's width
  DepthCompare compare;
  std::uint32_t depth_rows;

  // Allocates without clearing: call ClearRows on every row before drawing. depth_rows is clamped
  // to the height; a row's depth lives until the row ring_rows further down is cleared.
  Framebuffer(std::uint32_t width, std::uint32_t height, DepthCompare op, std::uint32_t ring_rows)
      : colour(width, height, Image::Uncleared{}),
        depth(std::size_t{width} * std::min(ring_rows, height)),
        compare(op),
        depth_rows(std::min(ring_rows, height)) {}
  Framebuffer(std::uint32_t width, std::uint32_t height, DepthCompare op = DepthCompare::kLess)
      : Framebuffer(width, height, op, height) {}

  std::uint32_t width() const { return colour.width; }
  std::uint32_t height() const { return colour.height; }
  std::size_t index(int px, int py) const { return std::size_t(py) * colour.width + std::size_t(px); }
  float* depth_row(int py) { return depth.data() + std::size_t(std::uint32_t(py) % depth_rows) * colour.width; }
  const float* depth_row(int py) const {
    return depth.data() + std::size_t(std::uint32_t(py) % depth_rows) * colour.width;
  }
  std::uint32_t colour_word(std::size_t i) const {  // the pixel's 4 bytes as one word (PackRgba)
    std::uint32_t word;
    std::memcpy(&word, colour.rgba.data() + 4 * i, 4);
    return word;
  }
};

// vkCmdBeginRenderPass's clears for rows [row_begin, row_end): colour, and depth to
// ClearDepth(fb.compare).
void ClearRows(Framebuffer& fb, int row_begin, int row_end, std::uint32_t clear_colour);

// One fragment: depth test, and on pass depth and colour writes. Returns whether it passed.
bool ShadeFragment(Framebuffer& fb, int px, int py, const DepthPlane& plane, std::uint32_t colour);

// All fragments of a covered span (the same result as ShadeFragment on each, faster).
void ShadeSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, std::uint32_t colour);
// The same with SwiftShader's plane and depth clamp.
void ShadeSpan(Framebuffer& fb, int py, Span span, const AnchoredPlane& plane, std::uint32_t colour);

// The same for a Gouraud triangle: each fragment that passes writes its interpolated colour.
void ShadeSmoothSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, const ColourPlanes& colour);
void ShadeSmoothSpan(Framebuffer& fb, int py, Span span, const AnchoredPlane& plane,
                     const AnchoredColourPlanes& colour);

}  // namespace twinraster::cpu
