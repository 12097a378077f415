// The CPU twin: renders a DrawList on the CPU following lavapipe's rasterization rules, so that the
// image equals the Vulkan/lavapipe image bit for bit.
#pragma once

#include "draw_list.hpp"
#include "image.hpp"

namespace twinraster {

// threads: 0 = std::thread::hardware_concurrency(). The image is identical for any thread count.
struct CpuOptions {
  unsigned threads = 0;
};

// setup = vertex processing + clipping + triangle setup, draw = clearing and rasterization,
// readback = building the Image.
struct CpuTimings {
  double setup_ms = 0, draw_ms = 0, readback_ms = 0;
};

// Throws std::invalid_argument for a malformed list (size 0 or over 16384, a mesh or vertex index
// out of range, a colour missing), as the GPU renderer does.
Image RenderOnCpu(const DrawList& list, const CpuOptions& options = {}, CpuTimings* timings = nullptr);

}  // namespace twinraster
