#include "gpu/instance_buffers.hpp"

#include <cstring>

namespace twinraster::gpu {

InstanceBuffers::InstanceBuffers(const VulkanContext& context, const DrawList& list, const DrawPlan& plan) {
  static_assert(sizeof(glm::mat4) == 64, "F is uploaded as 16 packed floats, column-major");
  buffers_.reserve(plan.buffer_sizes.size());
  for (const std::uint32_t size : plan.buffer_sizes) {
    buffers_.emplace_back(context, vk::DeviceSize{size} * sizeof(glm::mat4), vk::BufferUsageFlagBits::eVertexBuffer);
  }
  // The memory is host-coherent and the queue submission makes these writes visible to the GPU.
  for (const DrawBatch& batch : plan.batches) {
    if (!batch.instanced) continue;
    std::byte* destination = buffers_[batch.buffer].data() + std::size_t{batch.first_instance} * sizeof(glm::mat4);
    for (std::uint32_t i = 0; i < batch.count; ++i) {
      std::memcpy(destination + std::size_t{i} * sizeof(glm::mat4), &list.draws[batch.first_draw + i].F,
                  sizeof(glm::mat4));
    }
  }
}

}  // namespace twinraster::gpu
