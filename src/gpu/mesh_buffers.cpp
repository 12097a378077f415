#include "gpu/mesh_buffers.hpp"

#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

namespace twinraster::gpu {
namespace {

static_assert(sizeof(glm::vec3) == 3 * sizeof(float), "positions are uploaded as packed vec3");

// Checks the list (the renderers' common checks, then this device's limits) and lays the meshes
// out one after another.
MeshPlan PlanMeshes(const DrawList& list, const vk::PhysicalDeviceLimits& limits) {
  ValidateDrawList(list);  // an index out of range would make the GPU read outside the buffer
  MeshPlan plan;
  for (const DrawMesh& mesh : list.meshes) {
    plan.ranges.push_back(MeshRange{
        .first_corner = static_cast<std::uint32_t>(plan.triangles * 3),
        .corner_count = static_cast<std::uint32_t>(mesh.triangles.size() * 3),
    });
    plan.triangles += mesh.triangles.size();
    // Corner numbers (gl_VertexIndex) are unsigned 32-bit, and the colours must fit in one
    // storage-buffer binding.
    if (plan.triangles * 3 > std::numeric_limits<std::uint32_t>::max() ||
        plan.triangles * sizeof(std::uint32_t) > limits.maxStorageBufferRange) {
      throw std::invalid_argument("the draw list's meshes are too large for one draw");
    }
  }
  return plan;
}

// Each corner's vertex colour, packed as the vertex shader unpacks it, mesh after mesh.
void FillVertexColours(const DrawList& list, std::byte* out) {
  for (const DrawMesh& mesh : list.meshes) {
    for (const auto& triangle : mesh.triangles) {
      for (const std::uint32_t v : triangle) {
        const std::uint32_t packed = mesh.vertex_colours.empty() ? 0u : PackRgba8(mesh.vertex_colours[v]);
        std::memcpy(out, &packed, sizeof packed);
        out += sizeof packed;
      }
    }
  }
}

bool AnyVertexColours(const DrawList& list) {
  for (const DrawMesh& mesh : list.meshes) {
    if (!mesh.vertex_colours.empty()) return true;
  }
  return false;
}

}  // namespace

MeshBuffers::MeshBuffers(const VulkanContext& context, const DrawList& list)
    : plan_(PlanMeshes(list, context.limits())),
      corners_(context, plan_.triangles * 3 * sizeof(glm::vec3), vk::BufferUsageFlagBits::eVertexBuffer),
      colours_(context, plan_.triangles * sizeof(std::uint32_t), vk::BufferUsageFlagBits::eStorageBuffer) {
  // The memory is host-coherent and the queue submission makes these writes visible to the GPU.
  std::byte* corner = corners_.data();
  std::byte* colour = colours_.data();
  for (const DrawMesh& mesh : list.meshes) {
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      for (const std::uint32_t v : mesh.triangles[t]) {
        std::memcpy(corner, &mesh.positions[v], sizeof(glm::vec3));
        corner += sizeof(glm::vec3);
      }
      const std::uint32_t packed = PackRgba8(mesh.colours[t]);
      std::memcpy(colour, &packed, sizeof packed);
      colour += sizeof packed;
    }
  }
  if (AnyVertexColours(list)) {
    vertex_colours_.emplace(context, plan_.triangles * 3 * sizeof(std::uint32_t),
                            vk::BufferUsageFlagBits::eVertexBuffer);
    FillVertexColours(list, vertex_colours_->data());
  }
}

}  // namespace twinraster::gpu
