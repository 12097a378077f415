// What a lit draw list adds on the GPU: each triangle corner's normal in a vertex buffer beside
// the corner positions, each draw's LitInstance, and the lights, in storage buffers laid out as
// shaders/triangle.vert (LIT) reads them. Built only for a list with lighting.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/host_buffer.hpp"
#include "gpu/vulkan_context.hpp"

#include <cstdint>

namespace twinraster::gpu {

// One storage-buffer binding shows the shader this many LitInstances (112 MiB, inside the 128 MiB
// every Vulkan device allows in one binding), from a dynamic offset: range k holds draws
// [k · kLitInstancesPerRange, (k + 1) · kLitInstancesPerRange), and the renderer draws a lit scene
// of any size range by range (the last range's window ends with the buffer).
inline constexpr std::uint32_t kLitInstancesPerRange = 1u << 20;
inline constexpr vk::DeviceSize kLitInstanceBytes = 112;  // std430 LitInstance: mat4x3 + mat3

class LightBuffers {
 public:
  LightBuffers(const VulkanContext& context, const DrawList& list);

  vk::Buffer normals() const { return normals_.buffer(); }           // vec3 per corner (binding 2)
  vk::Buffer instances() const { return instances_.buffer(); }       // LitInstance per draw
  vk::DeviceSize instance_range() const { return instance_range_; }  // the binding's size
  vk::Buffer lights() const { return lights_.buffer(); }

 private:
  HostBuffer normals_;
  HostBuffer instances_;
  vk::DeviceSize instance_range_;
  HostBuffer lights_;
};

}  // namespace twinraster::gpu
