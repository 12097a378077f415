// What a lit draw list adds on the GPU: each triangle corner's normal in a vertex buffer beside
// the corner positions, each draw's LitInstance, and the lights, in storage buffers laid out as
// shaders/triangle.vert (LIT) reads them. Built only for a list with lighting.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/host_buffer.hpp"
#include "gpu/vulkan_context.hpp"

namespace twinraster::gpu {

class LightBuffers {
 public:
  // Throws std::invalid_argument if the list's instances do not fit one storage-buffer binding.
  LightBuffers(const VulkanContext& context, const DrawList& list);

  vk::Buffer normals() const { return normals_.buffer(); }      // vec3 per corner (binding 2)
  vk::Buffer instances() const { return instances_.buffer(); }  // LitInstance per draw
  vk::Buffer lights() const { return lights_.buffer(); }

 private:
  HostBuffer normals_;
  HostBuffer instances_;
  HostBuffer lights_;
};

}  // namespace twinraster::gpu
