#include "gpu/mesh_buffers.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace twinraster::gpu {
namespace {

using IndexTriple = std::array<std::uint32_t, 3>;
static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions are uploaded as packed vec3");
static_assert(sizeof(IndexTriple) == 3 * sizeof(std::uint32_t), "triangles as packed uint32s");

// Checks the list (the renderers' common checks, then this device's limits) and lays the meshes
// out one after another.
MeshPlan PlanMeshes(const DrawList& list, const vk::PhysicalDeviceLimits& limits) {
  ValidateDrawList(list);  // an index out of range would make the GPU read outside the buffer
  MeshPlan plan;
  for (std::size_t m = 0; m < list.meshes.size(); ++m) {
    const DrawMesh& mesh = list.meshes[m];
    plan.ranges.push_back(MeshRange{
        .first_vertex = static_cast<std::int32_t>(plan.vertices),
        .first_index = static_cast<std::uint32_t>(plan.triangles * 3),
        .index_count = static_cast<std::uint32_t>(mesh.triangles.size() * 3),
        .first_colour = static_cast<std::uint32_t>(plan.triangles),
    });
    plan.vertices += mesh.positions.size();
    plan.triangles += mesh.triangles.size();
    // vertexOffset is a signed 32-bit number, firstIndex an unsigned one, and the colours must
    // fit in one storage-buffer binding.
    if (plan.vertices > std::numeric_limits<std::int32_t>::max() ||
        plan.triangles * 3 > std::numeric_limits<std::uint32_t>::max() ||
        plan.triangles * sizeof(std::uint32_t) > limits.maxStorageBufferRange) {
      throw std::invalid_argument("the draw list's meshes are too large for one draw");
    }
  }
  return plan;
}

// memcpy with a null source is undefined even for 0 bytes, and an empty vector's data() may be
// null.
template <typename T>
void CopyAll(std::byte* destination, const std::vector<T>& values) {
  if (!values.empty()) std::memcpy(destination, values.data(), values.size() * sizeof(T));
}

}  // namespace

MeshBuffers::MeshBuffers(const VulkanContext& context, const DrawList& list)
    : plan_(PlanMeshes(list, context.limits())),
      geometry_(context, plan_.vertices * sizeof(glm::vec3) + plan_.triangles * sizeof(IndexTriple),
                vk::BufferUsageFlagBits::eVertexBuffer | vk::BufferUsageFlagBits::eIndexBuffer),
      colours_(context, plan_.triangles * sizeof(std::uint32_t),
               vk::BufferUsageFlagBits::eStorageBuffer) {
  // The memory is host-coherent and the queue submission makes these writes visible to the GPU.
  for (std::size_t m = 0; m < list.meshes.size(); ++m) {
    const DrawMesh& mesh = list.meshes[m];
    const MeshRange& range = plan_.ranges[m];
    CopyAll(geometry_.data() + std::size_t(range.first_vertex) * sizeof(glm::vec3), mesh.positions);
    CopyAll(geometry_.data() + index_offset() + std::size_t{range.first_index} * 4, mesh.triangles);
    std::byte* colour = colours_.data() + std::size_t{range.first_colour} * 4;
    for (const Rgb8& c : mesh.colours) {
      const std::uint32_t packed = PackRgba8(c);
      std::memcpy(colour, &packed, sizeof packed);
      colour += sizeof packed;
    }
  }
}

}  // namespace twinraster::gpu
