// The render pass and the graphics pipelines (shaders, fixed-function state, layout) every draw
// uses; none of it depends on the image size, so it is built once per GpuRenderer, and each
// pipeline only when a draw list first needs it (lavapipe compiles shaders at pipeline creation).
#pragma once

#include <glm/mat4x4.hpp>
#include <vulkan/vulkan_raii.hpp>

#include <cstddef>
#include <cstdint>

namespace twinraster::gpu {

constexpr vk::Format kColourFormat =
    vk::Format::eR8G8B8A8Unorm;  // UNORM: colours reach the PNG unchanged
constexpr vk::Format kDepthFormat = vk::Format::eD32Sfloat;

// The push-constant block of shaders/triangle.vert, byte for byte (std430: 64).
struct PushConstants {
  glm::mat4 F;  // DrawCall::F; glm is column-major like GLSL
};
static_assert(sizeof(PushConstants) == 64);

// Where the vertex shader reads F: a push constant per draw (one draw per instance, the
// chapter's Listing 10-5), or a per-instance vertex attribute (one draw for a run of instances).
enum class FSource { kPushConstant, kInstanceAttribute };

class Pipeline {
 public:
  explicit Pipeline(const vk::raii::Device& device);  // keeps a reference to `device`

  const vk::raii::RenderPass& render_pass() const { return render_pass_; }
  const vk::raii::DescriptorSetLayout& colour_set_layout() const { return colour_set_layout_; }
  const vk::raii::PipelineLayout& layout() const { return layout_; }
  // Depth test LESS for standard depth, GREATER for reversed Z (DrawList::reversed_z). Created
  // on first use.
  // on first use. Wireframe: polygonMode LINE, 1 pixel wide (needs the fillModeNonSolid feature).
  const vk::raii::Pipeline& pipeline(FSource source, bool reversed_z, bool wireframe);

 private:
  vk::raii::Pipeline Create(FSource source, bool reversed_z, bool wireframe) const;

  const vk::raii::Device* device_;
  vk::raii::RenderPass render_pass_ = nullptr;
  vk::raii::DescriptorSetLayout colour_set_layout_ = nullptr;  // binding 0: the triangle colours
  vk::raii::PipelineLayout layout_ = nullptr;
  // [F source][reversed Z][wireframe]: identical but for the vertex input, the depth compare op
  // and the polygon mode, which are baked into a Vulkan 1.0 pipeline.
  vk::raii::Pipeline pipelines_[2][2][2] = {{{nullptr, nullptr}, {nullptr, nullptr}},
                                            {{nullptr, nullptr}, {nullptr, nullptr}}};
};

}  // namespace twinraster::gpu
