#include "cpu/fragment_ops.hpp"

#include "cpu/lighting.hpp"
#include "cpu/platform.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace twinraster::cpu {

namespace {

// One cached depth allocation per thread, at most 64 MiB of it.
constexpr std::size_t kMaxCachedDepth = std::size_t{16} << 20;
thread_local FrameVector<float> t_cached_depth;

}  // namespace

DepthBuffer::DepthBuffer(std::size_t size) {
  if (t_cached_depth.size() >= size) {
    data_ = std::exchange(t_cached_depth, {});
  } else {
    data_.resize(size);  // uninitialized (FrameAllocator): ClearRows writes every row
  }
}

DepthBuffer::~DepthBuffer() {
  if (data_.size() <= kMaxCachedDepth && data_.size() > t_cached_depth.size()) t_cached_depth = std::move(data_);
}

DepthBuffer::DepthBuffer(DepthBuffer&& other) noexcept : data_(std::exchange(other.data_, {})) {}

namespace {

// The depth test at pixel px of a row, then the depth and colour writes where it passes, with
// every store unconditional (the old value where it fails), so that the rows' loops vectorize.
[[gnu::always_inline]] inline void TestAndWrite(float* depth, std::uint8_t* rgba, int px, float z, bool greater,
                                                std::uint32_t word) {
  const float stored = depth[px];
  const bool pass = greater ? z > stored : z < stored;  // DepthTest
  depth[px] = pass ? z : stored;
  std::uint32_t old;
  std::memcpy(&old, rgba + 4 * px, 4);
  const std::uint32_t written = pass ? word : old;
  std::memcpy(rgba + 4 * px, &written, 4);
}

// Written so that the compiler can vectorize it (no branches, every store unconditional), once per
// way of evaluating the depth plane (PlaneDepth, fused or not).
template <bool kFused>
[[gnu::always_inline]] inline void ShadeRowBody(float* depth, std::uint8_t* rgba, int begin, int end, float py,
                                                float a0, float dzdx, float dzdy, bool greater, std::uint32_t fill) {
  for (int px = begin; px < end; ++px) {
    const float x = static_cast<float>(px);
    float z = kFused ? std::fma(dzdy, py, std::fma(dzdx, x, a0)) : dzdy * py + (dzdx * x + a0);  // PlaneDepth
    z = z < 1.0f ? z : 1.0f;                                                                     // ClampDepth
    z = z > 0.0f ? z : 0.0f;
    TestAndWrite(depth, rgba, px, z, greater, fill);
  }
}

// On x86-64 a second copy of the fused row is built for CPUs with FMA (TWINRASTER_FMA_CLONES).
TWINRASTER_FMA_CLONES
void ShadeRowFused(float* depth, std::uint8_t* rgba, int begin, int end, float py, float a0, float dzdx, float dzdy,
                   bool greater, std::uint32_t fill) {
  ShadeRowBody<true>(depth, rgba, begin, end, py, a0, dzdx, dzdy, greater, fill);
}

void ShadeRowSeparate(float* depth, std::uint8_t* rgba, int begin, int end, float py, float a0, float dzdx, float dzdy,
                      bool greater, std::uint32_t fill) {
  ShadeRowBody<false>(depth, rgba, begin, end, py, a0, dzdx, dzdy, greater, fill);
}

// SwiftShader's row: its plane (never fused) and its clamp, max before min.
void ShadeAnchoredRow(float* depth, std::uint8_t* rgba, int begin, int end, float py, const AnchoredPlane& plane,
                      bool greater, std::uint32_t fill) {
  for (int px = begin; px < end; ++px) {
    const float z = ClampDepthMaxFirst(PlaneDepth(plane, static_cast<float>(px), py));
    TestAndWrite(depth, rgba, px, z, greater, fill);
  }
}

// Each device's depth clamp, for the smooth rows.
inline float Clamped(const DepthPlane& plane, float x, float py) { return ClampDepth(PlaneDepth(plane, x, py)); }
inline float Clamped(const AnchoredPlane& plane, float x, float py) {
  return ClampDepthMaxFirst(PlaneDepth(plane, x, py));
}

// ShadeRow for a Gouraud triangle: every pixel's colour is computed (ColourAt, then PackUnorm) and
// written where the depth test passes, without branches, so that the compiler vectorizes it.
template <class Plane>
[[gnu::always_inline]] inline void ShadeSmoothRowBody(float* depth, std::uint8_t* rgba, int begin, int end, float py,
                                                      const Plane& plane, const ColourPlanesOf<Plane>& colour,
                                                      bool greater) {
  for (int px = begin; px < end; ++px) {
    const float x = static_cast<float>(px);
    const float z = Clamped(plane, x, py);
    TestAndWrite(depth, rgba, px, z, greater, PackUnorm(ColourAt(colour, x, py)));
  }
}

TWINRASTER_FMA_CLONES
void ShadeSmoothRow(float* depth, std::uint8_t* rgba, int begin, int end, float py, const DepthPlane& plane,
                    const ColourPlanes& colour, bool greater) {
  ShadeSmoothRowBody(depth, rgba, begin, end, py, plane, colour, greater);
}

// SwiftShader's never fuses: one copy.
void ShadeSmoothRow(float* depth, std::uint8_t* rgba, int begin, int end, float py, const AnchoredPlane& plane,
                    const AnchoredColourPlanes& colour, bool greater) {
  ShadeSmoothRowBody(depth, rgba, begin, end, py, plane, colour, greater);
}

}  // namespace

void ClearRows(Framebuffer& fb, int row_begin, int row_end, std::uint32_t clear_colour) {
  const float clear_depth = ClearDepth(fb.compare);
  for (int py = row_begin; py < row_end; ++py) std::fill_n(fb.depth_row(py), fb.width(), clear_depth);
  const std::size_t begin = fb.index(0, row_begin), end = fb.index(0, row_end);
  std::uint8_t* rgba = fb.colour.rgba.data();
  for (std::size_t i = begin; i < end; ++i) std::memcpy(rgba + 4 * i, &clear_colour, 4);
}

bool ShadeFragment(Framebuffer& fb, int px, int py, const DepthPlane& plane, std::uint32_t colour) {
  const std::size_t i = fb.index(px, py);
  const float z = DepthAt(plane, px, py);
  float& stored = fb.depth_row(py)[px];
  if (!DepthTest(fb.compare, z, stored)) return false;
  stored = z;
  std::memcpy(fb.colour.rgba.data() + 4 * i, &colour, 4);
  return true;
}

void ShadeSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, std::uint32_t colour) {
  const std::size_t row = fb.index(0, py);
  const bool greater = fb.compare == DepthCompare::kGreater;
  if (plane.fused) {
    ShadeRowFused(fb.depth_row(py), fb.colour.rgba.data() + 4 * row, span.begin, span.end, static_cast<float>(py),
                  plane.a0, plane.dzdx, plane.dzdy, greater, colour);
  } else {
    ShadeRowSeparate(fb.depth_row(py), fb.colour.rgba.data() + 4 * row, span.begin, span.end, static_cast<float>(py),
                     plane.a0, plane.dzdx, plane.dzdy, greater, colour);
  }
}

void ShadeSpan(Framebuffer& fb, int py, Span span, const AnchoredPlane& plane, std::uint32_t colour) {
  const std::size_t row = fb.index(0, py);
  ShadeAnchoredRow(fb.depth_row(py), fb.colour.rgba.data() + 4 * row, span.begin, span.end, static_cast<float>(py),
                   plane, fb.compare == DepthCompare::kGreater, colour);
}

void ShadeSmoothSpan(Framebuffer& fb, int py, Span span, const DepthPlane& plane, const ColourPlanes& colour) {
  const std::size_t row = fb.index(0, py);
  ShadeSmoothRow(fb.depth_row(py), fb.colour.rgba.data() + 4 * row, span.begin, span.end, static_cast<float>(py), plane,
                 colour, fb.compare == DepthCompare::kGreater);
}

void ShadeSmoothSpan(Framebuffer& fb, int py, Span span, const AnchoredPlane& plane,
                     const AnchoredColourPlanes& colour) {
  const std::size_t row = fb.index(0, py);
  ShadeSmoothRow(fb.depth_row(py), fb.colour.rgba.data() + 4 * row, span.begin, span.end, static_cast<float>(py), plane,
                 colour, fb.compare == DepthCompare::kGreater);
}

}  // namespace twinraster::cpu
