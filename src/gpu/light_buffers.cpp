#include "gpu/light_buffers.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cstring>

namespace twinraster::gpu {
namespace {

// std430 layouts of triangle.vert's LitInstance and Light: a vec3 (and each column of mat4x3 and
// mat3) takes 16 bytes.
struct Std430Instance {
  std::array<glm::vec4, 4> model;   // mat4x3: the columns, w unused
  std::array<glm::vec4, 3> normal;  // mat3
};
static_assert(sizeof(Std430Instance) == kLitInstanceBytes);
struct Std430Light {
  glm::vec3 vector;
  float intensity;
  std::uint32_t point;
  std::uint32_t padding[3];
};
static_assert(sizeof(Std430Light) == 32);
constexpr std::size_t kLightsHeader = 16;  // float ambient, uint count, then the array at 16

std::uint64_t Corners(const DrawList& list) {
  std::uint64_t triangles = 0;
  for (const DrawMesh& mesh : list.meshes) triangles += mesh.triangles.size();
  return triangles * 3;
}

static_assert(kLitInstancesPerRange * kLitInstanceBytes <= (vk::DeviceSize{1} << 27),
              "a range must fit the smallest maxStorageBufferRange Vulkan allows");

}  // namespace

LightBuffers::LightBuffers(const VulkanContext& context, const DrawList& list)
    : normals_(context, Corners(list) * sizeof(glm::vec3), vk::BufferUsageFlagBits::eVertexBuffer),
      instances_(context, vk::DeviceSize{list.draws.size()} * kLitInstanceBytes,
                 vk::BufferUsageFlagBits::eStorageBuffer),
      instance_range_(std::min<vk::DeviceSize>(std::max<std::size_t>(list.draws.size(), 1), kLitInstancesPerRange) *
                      kLitInstanceBytes),
      lights_(context, kLightsHeader + list.lighting->lights.size() * sizeof(Std430Light),
              vk::BufferUsageFlagBits::eStorageBuffer) {
  // Corner normals in the corner buffer's order; an unlit mesh's corners get zeros (unread).
  std::byte* normal = normals_.data();
  for (const DrawMesh& mesh : list.meshes) {
    const std::size_t bytes = mesh.triangles.size() * 3 * sizeof(glm::vec3);
    if (mesh.shading == Shading::kUnlit) {
      std::memset(normal, 0, bytes);
    } else {
      static_assert(sizeof(std::array<glm::vec3, 3>) == 3 * sizeof(glm::vec3));
      std::memcpy(normal, mesh.normals.data(), bytes);
    }
    normal += bytes;
  }

  std::byte* instance = instances_.data();
  for (const LitInstance& lit : list.lighting->instances) {
    Std430Instance packed{};
    for (int c = 0; c < 4; ++c) packed.model[static_cast<std::size_t>(c)] = glm::vec4(lit.model[c], 0.0f);
    for (int c = 0; c < 3; ++c) packed.normal[static_cast<std::size_t>(c)] = glm::vec4(lit.normal[c], 0.0f);
    std::memcpy(instance, &packed, sizeof packed);
    instance += sizeof packed;
  }

  const float ambient = list.lighting->ambient;
  const auto count = static_cast<std::uint32_t>(list.lighting->lights.size());
  std::memset(lights_.data(), 0, kLightsHeader);
  std::memcpy(lights_.data(), &ambient, sizeof ambient);
  std::memcpy(lights_.data() + 4, &count, sizeof count);
  std::byte* light = lights_.data() + kLightsHeader;
  for (const DrawLight& l : list.lighting->lights) {
    const Std430Light packed{.vector = l.vector, .intensity = l.intensity, .point = l.point ? 1u : 0u, .padding = {}};
    std::memcpy(light, &packed, sizeof packed);
    light += sizeof packed;
  }
}

}  // namespace twinraster::gpu
