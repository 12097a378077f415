// The draw list's meshes packed for the GPU: all positions then all indices in one buffer, all
// triangle colours in a storage buffer, and where each mesh starts in them.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/host_buffer.hpp"
#include "gpu/vulkan_context.hpp"

#include <cstdint>
#include <vector>

namespace twinraster::gpu {

// Where one mesh starts in the shared buffers; a draw of the mesh uses exactly these numbers.
struct MeshRange {
  std::int32_t first_vertex = 0;   // vkCmdDrawIndexed's vertexOffset, so indices stay mesh-local
  std::uint32_t first_index = 0;   // vkCmdDrawIndexed's firstIndex
  std::uint32_t index_count = 0;   // 3 per triangle; 0 for a mesh without triangles
  std::uint32_t first_colour = 0;  // the mesh's first triangle overall: the shaders' first_colour
};

// Packs a colour as unpackUnorm4x8 reads it: red in the lowest byte, alpha 255.
constexpr std::uint32_t PackRgba8(Rgb8 c) {
  return std::uint32_t{c.r} | std::uint32_t{c.g} << 8 | std::uint32_t{c.b} << 16 | 0xFF000000u;
}

// Every mesh's range, and the totals the buffers are sized from.
struct MeshPlan {
  std::vector<MeshRange> ranges;  // ranges[i] belongs to DrawList::meshes[i]
  std::uint64_t vertices = 0, triangles = 0;
};

class MeshBuffers {
 public:
  // Throws std::invalid_argument if the list is malformed: a draw of a missing mesh, an index
  // past the mesh's vertices, a colour count unlike the triangle count, or more than fits.
  MeshBuffers(const VulkanContext& context, const DrawList& list);

  vk::Buffer geometry() const { return geometry_.buffer(); }  // positions (binding 0), then indices
  vk::DeviceSize index_offset() const { return plan_.vertices * sizeof(glm::vec3); }
  vk::Buffer colours() const { return colours_.buffer(); }
  const MeshRange& range(std::uint32_t mesh) const { return plan_.ranges[mesh]; }

 private:
  MeshPlan plan_;  // first: the buffers below are sized from it
  HostBuffer geometry_;
  HostBuffer colours_;
};

}  // namespace twinraster::gpu
