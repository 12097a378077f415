// The draw list's meshes packed for the GPU: every triangle's three corners in turn in one vertex
// buffer, mesh after mesh, all triangle colours in a storage buffer in the same order, and where
// each mesh starts in them. Corner v belongs to triangle v / 3, whose colour is colours[v / 3]:
// the shaders need no index buffer, no per-draw offset and no gl_PrimitiveID. When some mesh has
// vertex colours, a third buffer holds each corner's vertex colour in the corner buffer's order.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/host_buffer.hpp"
#include "gpu/vulkan_context.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace twinraster::gpu {

// Where one mesh starts in the shared buffers; a draw of the mesh uses exactly these numbers.
struct MeshRange {
  std::uint32_t first_corner = 0;  // vkCmdDraw's firstVertex: 3 x the mesh's first triangle overall
  std::uint32_t corner_count = 0;  // vkCmdDraw's vertexCount: 3 per triangle; 0 for no triangles
};

// Packs a colour as unpackUnorm4x8 reads it: red in the lowest byte, alpha 255.
constexpr std::uint32_t PackRgba8(Rgb8 c) {
  return std::uint32_t{c.r} | std::uint32_t{c.g} << 8 | std::uint32_t{c.b} << 16 | 0xFF000000u;
}

// Every mesh's range, and the totals the buffers are sized from.
struct MeshPlan {
  std::vector<MeshRange> ranges;  // ranges[i] belongs to DrawList::meshes[i]
  std::uint64_t triangles = 0;
};

class MeshBuffers {
 public:
  // Throws std::invalid_argument if the list is malformed: a draw of a missing mesh, an index
  // past the mesh's vertices, a colour count unlike the triangle count, or more than fits.
  MeshBuffers(const VulkanContext& context, const DrawList& list);

  vk::Buffer corners() const { return corners_.buffer(); }  // vec3 positions (binding 0)
  vk::Buffer colours() const { return colours_.buffer(); }
  // Packed RGBA8 per corner (binding 3), zero for a mesh without vertex colours (unread); only
  // when some mesh has them, so a list without them uploads exactly what it did before.
  const std::optional<HostBuffer>& vertex_colours() const { return vertex_colours_; }
  const MeshRange& range(std::uint32_t mesh) const { return plan_.ranges[mesh]; }

 private:
  MeshPlan plan_;  // first: the buffers below are sized from it
  HostBuffer corners_;
  HostBuffer colours_;
  std::optional<HostBuffer> vertex_colours_;
};

}  // namespace twinraster::gpu
