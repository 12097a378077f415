// The F matrices of a draw plan's instanced batches, in host-visible buffers that the instanced
// vertex shader reads as a per-instance attribute (binding 1).
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/draw_batches.hpp"
#include "gpu/host_buffer.hpp"
#include "gpu/vulkan_context.hpp"

#include <vector>

namespace twinraster::gpu {

class InstanceBuffers {
 public:
  InstanceBuffers(const VulkanContext& context, const DrawList& list, const DrawPlan& plan);

  vk::Buffer buffer(std::uint32_t index) const { return buffers_[index].buffer(); }

 private:
  std::vector<HostBuffer> buffers_;  // buffers_[i] holds plan.buffer_sizes[i] matrices
};

}  // namespace twinraster::gpu
