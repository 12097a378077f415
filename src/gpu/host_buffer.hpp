// A Vulkan buffer in host-visible, host-coherent memory that stays mapped for its whole life:
// how the renderer uploads meshes and reads pixels back.
#pragma once

#include "gpu/vulkan_context.hpp"

#include <cstddef>

namespace twinraster::gpu {

class HostBuffer {
 public:
  // `size` may be 0: Vulkan forbids empty buffers, so a few bytes are allocated instead.
  HostBuffer(const VulkanContext& context, vk::DeviceSize size, vk::BufferUsageFlags usage);

  vk::Buffer buffer() const { return *buffer_; }
  std::byte* data() const { return data_; }  // the mapped bytes, valid while this object lives

 private:
  // Memory first, so the buffer is destroyed before the memory bound to it is freed.
  vk::raii::DeviceMemory memory_ = nullptr;  // freeing it also unmaps it
  vk::raii::Buffer buffer_ = nullptr;
  std::byte* data_ = nullptr;
};

}  // namespace twinraster::gpu
