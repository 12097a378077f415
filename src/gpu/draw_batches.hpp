// How a draw list becomes Vulkan draw commands: runs of consecutive instances of one mesh, each
// drawn either as one push constant and one draw per instance, or as one instanced draw reading F
// from a buffer. Planning only, no Vulkan, so it is testable on its own.
#pragma once

#include "chain/draw_list.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::gpu {

// kAuto instances a run of at least kInstancingThreshold draws of one mesh and pushes F per draw
// otherwise; kAlways and kNever force one path (tests and the bench use them to show that both
// give the same pixels, and where they cross over).
enum class Instancing { kAuto, kAlways, kNever };

// Below this many consecutive draws of one mesh, per-draw push constants cost no more than
// filling an instance buffer (docs/million-cubes.md measures the crossover).
inline constexpr std::uint32_t kInstancingThreshold = 8;
// F matrices per instance buffer: 64 MiB each, far inside any device's allocation limit, so a
// scene with millions of instances is split across buffers instead of failing.
inline constexpr std::uint32_t kInstancesPerBuffer = 1u << 20;

struct DrawBatch {
  std::uint32_t mesh = 0;
  std::size_t first_draw = 0;  // index into DrawList::draws
  std::uint32_t count = 0;     // consecutive draws of `mesh`
  bool instanced = false;
  std::uint32_t buffer = 0;          // instanced: which instance buffer holds their F
  std::uint32_t first_instance = 0;  // instanced: the first F's index in it (firstInstance)
};

struct DrawPlan {
  std::vector<DrawBatch> batches;           // in draw-list order, covering every draw once
  std::vector<std::uint32_t> buffer_sizes;  // F matrices in each instance buffer
};

// `per_buffer` is a parameter only so that tests can exercise the splitting with small lists.
DrawPlan PlanDraws(const DrawList& list, Instancing mode, std::uint32_t per_buffer = kInstancesPerBuffer);

}  // namespace twinraster::gpu
