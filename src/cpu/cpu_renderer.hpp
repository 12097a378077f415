// The CPU twin: renders a DrawList on the CPU following one Vulkan's rasterization rules (lavapipe's
// or SwiftShader's, chosen by twin_rules/twin_rules.hpp), so that the image equals that device's
// bit for bit. It does not choose the rules, and it does not read a device.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/raster_rules.hpp"
#include "image/image.hpp"

#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// Left to choose (CpuOptions::threads 0), the twin draws a frame of at most this many pixels and
// this many triangles (every draw's mesh, before clipping) on one thread, and a larger one on
// every core.
inline constexpr std::uint64_t kOneThreadPixels = 1024 * 1024;
inline constexpr std::uint64_t kOneThreadTriangles = 4096;

// threads: how many threads set up and draw the frame, at most one per 16-row band; 0 = one for a
// frame within kOneThreadPixels and kOneThreadTriangles, else std::thread::hardware_concurrency().
// The image is identical for any thread count.
struct CpuOptions {
  unsigned threads = 0;
  // Triangles (and vertices) set up per chunk; 0: the default (chunk_assembly.hpp's ChunkBudget). The
  // image is identical for any value; tests use small ones to exercise the streaming.
  std::size_t chunk_triangles = 0;
  // Skip triangles hidden in a 16x16 tile by what is already drawn (cpu/depth_tiles.hpp). Exact,
  // so the image is the same without; off only to measure what it saves and to test that.
  bool depth_tiles = true;
  // Which device's arithmetic to copy (twin_rules/twin_rules.hpp chooses
  // it for a device and CPU path).
  RasterRules rules{};
};

// The twin as a device reports itself: the subPixelPrecisionBits of the device its rules copy (8
// for lavapipe, 4 for SwiftShader), and lines drawn strictly (strictLines), which is how the
// verifier judges the twin's own images.
struct TwinLimits {
  int subpixel_bits = 0;
  bool strict_lines = true;
};
TwinLimits TwinDeviceLimits(const RasterRules& rules = {});

// setup = vertex processing + clipping + triangle setup, draw = clearing and rasterization,
// readback = building the Image.
struct CpuTimings {
  double setup_ms = 0, draw_ms = 0, readback_ms = 0;
  unsigned threads = 0;      // the threads actually used: at most one per 16-row band
  std::uint64_t hidden = 0;  // triangles skipped in a band because the depth tiles hid them there
};

// Throws std::invalid_argument for a malformed list (size 0 or over 16384, a mesh or vertex index
// out of range, a colour missing), as the GPU renderer does.
Image RenderOnCpu(const DrawList& list, const CpuOptions& options = {}, CpuTimings* timings = nullptr);

// Clip-space positions from some other vertex stage: one vector per draw, holding that draw's mesh
// vertices transformed.
using ClipPositions = std::vector<std::vector<glm::vec4>>;

// Everything after the vertex stage (clipping onward) on positions another method computed, so
// that ways of computing the chain can be compared by the images they make. Throws
// std::invalid_argument when `clip` does not match the list's draws.
Image RasterizeClipSpace(const DrawList& list, const ClipPositions& clip, const CpuOptions& options = {},
                         CpuTimings* timings = nullptr);

}  // namespace twinraster::cpu
