// What the GPU-versus-CPU tests share: one validated Vulkan renderer for the whole run, and a
// check that renders a draw list on both backends and explains any difference.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image.hpp"
#include "image/image_compare.hpp"

#include <string>

namespace twinraster::test {

// Created on first use with the validation layer and synchronization validation on.
GpuRenderer& SharedGpu();

struct TwinResult {
  Image gpu, cpu;
  Comparison comparison;
  std::string Describe() const;  // size, differing pixels, and the first few that differ
};

TwinResult RenderTwins(const DrawList& list);

// Fails the current test if the validation layer said anything since the last call.
void RequireNoValidationMessages();

}  // namespace twinraster::test
