#include "gpu/host_buffer.hpp"

#include <algorithm>

namespace twinraster::gpu {

HostBuffer::HostBuffer(const VulkanContext& context, vk::DeviceSize size, vk::BufferUsageFlags usage) {
  const vk::raii::Device& device = context.device();
  buffer_ = vk::raii::Buffer(device, vk::BufferCreateInfo{
                                         .size = std::max<vk::DeviceSize>(size, 16),
                                         .usage = usage,
                                         .sharingMode = vk::SharingMode::eExclusive,
                                     });
  const vk::MemoryRequirements requirements = buffer_.getMemoryRequirements();
  // Coherent memory needs no flush after writing nor invalidate before reading; the queue
  // submission and the TRANSFER -> HOST barrier do the rest. Cached memory makes reads fast.
  memory_ = vk::raii::DeviceMemory(
      device, vk::MemoryAllocateInfo{
                  .allocationSize = requirements.size,
                  .memoryTypeIndex = context.FindMemoryType(
                      requirements.memoryTypeBits,
                      vk::MemoryPropertyFlagBits::eHostVisible | vk::MemoryPropertyFlagBits::eHostCoherent,
                      vk::MemoryPropertyFlagBits::eHostCached),
              });
  buffer_.bindMemory(*memory_, 0);
  data_ = static_cast<std::byte*>(memory_.mapMemory(0, VK_WHOLE_SIZE));
}

}  // namespace twinraster::gpu
