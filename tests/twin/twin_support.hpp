// What the GPU-versus-CPU tests share: one validated Vulkan renderer for the whole run, and a
// check that renders a draw list on both backends and explains any difference.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image.hpp"
#include "image/image_compare.hpp"
#include "twin_rules/twin_rules.hpp"

#include <string>

namespace twinraster::test {

// Created on first use with the validation layer and synchronization validation on; one per
// way of feeding F to the vertex shader.
gpu::GpuRenderer& SharedGpu(gpu::Instancing instancing = gpu::Instancing::kNever);

// The list drawn three ways: on the GPU one push constant per draw, on the GPU with every run of
// instances drawn instanced, and on the CPU twin. All three must agree.
struct TwinResult {
  Image gpu, gpu_instanced, cpu;
  Comparison comparison;            // gpu against cpu
  Comparison instanced_comparison;  // gpu_instanced against cpu
  bool Equal() const { return comparison.Equal() && instanced_comparison.Equal(); }
  std::string Describe() const;  // size, differing pixels, and the first few that differ
};

// Chromium's SwiftShader (Debian's chromium package), created on first use with the validation
// layer and released when the run ends, as the shared lavapipe renderers are.
gpu::GpuRenderer& SharedSwiftShader();

// The rules the twin follows against SharedGpu's device on this machine's CPU path, chosen as
// render chooses them (twin_rules/twin_rules.hpp).
const twin_rules::TwinRules& SharedTwinRules();

// `options` with those rules. Throws (failing the test, never skipping it) when the twin has no
// bit-exact rules for this lavapipe: a GPU == CPU test proves nothing then.
cpu::CpuOptions TwinOptions(cpu::CpuOptions options = {});

TwinResult RenderTwins(const DrawList& list);

// Fails the current test if the validation layer said anything since the last call.
void RequireNoValidationMessages();

}  // namespace twinraster::test
