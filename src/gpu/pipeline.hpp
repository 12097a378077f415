// The render pass and the graphics pipelines (shaders, fixed-function state, layout) every draw
// uses; none of it depends on the image size, so it is built once per GpuRenderer, and each
// pipeline only when a draw list first needs it (lavapipe compiles shaders at pipeline creation).
#pragma once

#include "scene/scene.hpp"

#include <glm/mat4x4.hpp>
#include <vulkan/vulkan_raii.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::gpu {

constexpr vk::Format kColourFormat = vk::Format::eR8G8B8A8Unorm;  // UNORM: colours reach the PNG unchanged
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

// The push-constant block of shaders/triangle.vert, byte for byte (std430: 64).
struct PushConstants {
  glm::mat4 F;  // DrawCall::F; glm is column-major like GLSL
};
static_assert(sizeof(PushConstants) == 64);

// The lit shaders' push-constant block (triangle.vert with LIT): F, and the number that, added
// to gl_InstanceIndex, is the draw's index in DrawList::draws (where its LitInstance is).
struct LitPushConstants {
  glm::mat4 F;
  std::uint32_t draw = 0;
};
static_assert(sizeof(LitPushConstants) == 68);

// Where the vertex shader reads F: a push constant per draw (one draw per instance, the
// chapter's Listing 10-5), or a per-instance vertex attribute (one draw for a run of instances).
enum class FSource { kPushConstant, kInstanceAttribute };

class Pipeline {
 public:
  explicit Pipeline(const vk::raii::Device& device);  // keeps a reference to `device`

  const vk::raii::RenderPass& render_pass() const { return render_pass_; }
  // Unlit: binding 0, the triangle colours (fragment stage). Lit: binding 0, the base colours,
  // 1, the LitInstances (through a dynamic offset: light_buffers.hpp), 2, the lights (all vertex
  // stage).
  const vk::raii::DescriptorSetLayout& set_layout(bool lit) const { return lit ? lit_set_layout_ : colour_set_layout_; }
  const vk::raii::PipelineLayout& layout(bool lit) const { return lit ? lit_layout_ : layout_; }
  // Depth test LESS for standard depth, GREATER for reversed Z (DrawList::reversed_z).
  // Wireframe: polygonMode LINE, 1 pixel wide (needs the fillModeNonSolid feature), unlit only.
  // Vertex colours: each corner's colour from binding 3 (location 6), filled triangles only.
  // Created on first use.
  const vk::raii::Pipeline& pipeline(Shading shading, bool vertex_colours, FSource source, bool reversed_z,
                                     bool wireframe);

 private:
  vk::raii::Pipeline Create(Shading shading, bool vertex_colours, FSource source, bool reversed_z,
                            bool wireframe) const;

  const vk::raii::Device* device_;
  vk::raii::RenderPass render_pass_ = nullptr;
  vk::raii::DescriptorSetLayout colour_set_layout_ = nullptr;
  vk::raii::PipelineLayout layout_ = nullptr;
  vk::raii::DescriptorSetLayout lit_set_layout_ = nullptr;
  vk::raii::PipelineLayout lit_layout_ = nullptr;
  // One per (shading, vertex colours, F source, reversed Z, wireframe): identical but for the
  // shaders, the vertex input, the depth compare op and the polygon mode, which are baked into a
  // Vulkan 1.0 pipeline.
  std::vector<vk::raii::Pipeline> pipelines_;
};

}  // namespace twinraster::gpu
