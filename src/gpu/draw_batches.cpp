#include "gpu/draw_batches.hpp"

#include <algorithm>
#include <stdexcept>

namespace twinraster::gpu {

DrawPlan PlanDraws(const DrawList& list, Instancing mode, std::uint32_t per_buffer) {
  if (per_buffer == 0) throw std::invalid_argument("PlanDraws: per_buffer must be positive");
  DrawPlan plan;
  const std::size_t n = list.draws.size();
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    while (end < n && list.draws[end].mesh == list.draws[begin].mesh) ++end;
    const std::size_t run = end - begin;
    const bool instanced = mode == Instancing::kAlways || (mode == Instancing::kAuto && run >= kInstancingThreshold);
    if (!instanced) {
      // One batch per run; the renderer pushes F and draws once per draw in it. Runs longer
      // than 2^32 draws cannot occur: scenes are limited far below that.
      plan.batches.push_back(
          DrawBatch{.mesh = list.draws[begin].mesh, .first_draw = begin, .count = static_cast<std::uint32_t>(run)});
    } else {
      // Fill instance buffers in order; a run that reaches the end of one continues in the next.
      for (std::size_t at = begin; at < end;) {
        if (plan.buffer_sizes.empty() || plan.buffer_sizes.back() == per_buffer) plan.buffer_sizes.push_back(0);
        std::uint32_t& used = plan.buffer_sizes.back();
        const auto count = static_cast<std::uint32_t>(std::min<std::size_t>(end - at, per_buffer - used));
        plan.batches.push_back(DrawBatch{.mesh = list.draws[begin].mesh,
                                         .first_draw = at,
                                         .count = count,
                                         .instanced = true,
                                         .buffer = static_cast<std::uint32_t>(plan.buffer_sizes.size() - 1),
                                         .first_instance = used});
        used += count;
        at += count;
      }
    }
    begin = end;
  }
  return plan;
}

}  // namespace twinraster::gpu
