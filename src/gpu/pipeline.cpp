#include "gpu/pipeline.hpp"

#include "shaders/lit_flat.frag.h"
#include "shaders/lit_flat.vert.h"
#include "shaders/lit_flat_instanced.vert.h"
#include "shaders/lit_flat_vertex_colours.vert.h"
#include "shaders/lit_flat_vertex_colours_instanced.vert.h"
#include "shaders/lit_gouraud.frag.h"
#include "shaders/lit_gouraud.vert.h"
#include "shaders/lit_gouraud_instanced.vert.h"
#include "shaders/lit_gouraud_vertex_colours.vert.h"
#include "shaders/lit_gouraud_vertex_colours_instanced.vert.h"
#include "shaders/triangle.frag.h"
#include "shaders/triangle.vert.h"
#include "shaders/triangle_instanced.vert.h"
#include "shaders/vertex_colours.vert.h"
#include "shaders/vertex_colours_instanced.vert.h"

#include <array>
#include <stdexcept>
#include <vector>

namespace twinraster::gpu {
namespace {

vk::raii::RenderPass CreateRenderPass(const vk::raii::Device& device) {
  const std::array attachments = {
      // Colour: cleared, kept, and left ready for the copy to the readback buffer.
      vk::AttachmentDescription{
          .format = kColourFormat,
          .samples = vk::SampleCountFlagBits::e1,
          .loadOp = vk::AttachmentLoadOp::eClear,
          .storeOp = vk::AttachmentStoreOp::eStore,
          .stencilLoadOp = vk::AttachmentLoadOp::eDontCare,
          .stencilStoreOp = vk::AttachmentStoreOp::eDontCare,
          .initialLayout = vk::ImageLayout::eUndefined,  // old contents are cleared anyway
          .finalLayout = vk::ImageLayout::eTransferSrcOptimal,
      },
      // Depth: cleared (to 1.0, or 0.0 for reversed Z: the value is given when the pass begins)
      // and thrown away after the pass.
      vk::AttachmentDescription{
          .format = kDepthFormat,
          .samples = vk::SampleCountFlagBits::e1,
          .loadOp = vk::AttachmentLoadOp::eClear,
          .storeOp = vk::AttachmentStoreOp::eDontCare,
          .stencilLoadOp = vk::AttachmentLoadOp::eDontCare,
          .stencilStoreOp = vk::AttachmentStoreOp::eDontCare,
          .initialLayout = vk::ImageLayout::eUndefined,
          .finalLayout = vk::ImageLayout::eDepthStencilAttachmentOptimal,
      },
  };
  const vk::AttachmentReference colour_ref{0, vk::ImageLayout::eColorAttachmentOptimal};
  const vk::AttachmentReference depth_ref{1, vk::ImageLayout::eDepthStencilAttachmentOptimal};
  const vk::SubpassDescription subpass{
      .pipelineBindPoint = vk::PipelineBindPoint::eGraphics,
      .colorAttachmentCount = 1,
      .pColorAttachments = &colour_ref,
      .pDepthStencilAttachment = &depth_ref,
  };
  const std::array dependencies = {
      // The images are reused by the next Render() of the same size: its clears must wait for
      // this frame's copy out of the colour image (write-after-read) and its depth writes
      // (write-after-write).
      vk::SubpassDependency{
          .srcSubpass = VK_SUBPASS_EXTERNAL,
          .dstSubpass = 0,
          .srcStageMask = vk::PipelineStageFlagBits::eTransfer | vk::PipelineStageFlagBits::eLateFragmentTests,
          .dstStageMask = vk::PipelineStageFlagBits::eColorAttachmentOutput |
                          vk::PipelineStageFlagBits::eEarlyFragmentTests |
                          vk::PipelineStageFlagBits::eLateFragmentTests,
          .srcAccessMask = vk::AccessFlagBits::eDepthStencilAttachmentWrite,
          .dstAccessMask = vk::AccessFlagBits::eColorAttachmentWrite | vk::AccessFlagBits::eDepthStencilAttachmentRead |
                           vk::AccessFlagBits::eDepthStencilAttachmentWrite,
      },
      // The copy to the readback buffer reads what the pass wrote (COLOR_ATTACHMENT_OUTPUT ->
      // TRANSFER); the final layout transition happens between the two.
      vk::SubpassDependency{
          .srcSubpass = 0,
          .dstSubpass = VK_SUBPASS_EXTERNAL,
          .srcStageMask = vk::PipelineStageFlagBits::eColorAttachmentOutput,
          .dstStageMask = vk::PipelineStageFlagBits::eTransfer,
          .srcAccessMask = vk::AccessFlagBits::eColorAttachmentWrite,
          .dstAccessMask = vk::AccessFlagBits::eTransferRead,
      },
  };
  return vk::raii::RenderPass(device, vk::RenderPassCreateInfo{
                                          .attachmentCount = attachments.size(),
                                          .pAttachments = attachments.data(),
                                          .subpassCount = 1,
                                          .pSubpasses = &subpass,
                                          .dependencyCount = dependencies.size(),
                                          .pDependencies = dependencies.data(),
                                      });
}

template <std::size_t N>
vk::raii::ShaderModule CreateShaderModule(const vk::raii::Device& device, const std::uint32_t (&words)[N]) {
  return vk::raii::ShaderModule(device, vk::ShaderModuleCreateInfo{.codeSize = sizeof words, .pCode = words});
}

// triangle.vert compiled with VERTEX_COLOURS (shaders/CMakeLists.txt).
vk::raii::ShaderModule VertexColourShader(const vk::raii::Device& device, Shading shading, bool instanced) {
  switch (shading) {
    case Shading::kFlat:
      return instanced ? CreateShaderModule(device, lit_flat_vertex_colours_instanced_vert_spv)
                       : CreateShaderModule(device, lit_flat_vertex_colours_vert_spv);
    case Shading::kGouraud:
      return instanced ? CreateShaderModule(device, lit_gouraud_vertex_colours_instanced_vert_spv)
                       : CreateShaderModule(device, lit_gouraud_vertex_colours_vert_spv);
    case Shading::kUnlit: break;
  }
  return instanced ? CreateShaderModule(device, vertex_colours_instanced_vert_spv)
                   : CreateShaderModule(device, vertex_colours_vert_spv);
}

vk::raii::ShaderModule VertexShader(const vk::raii::Device& device, Shading shading, bool vertex_colours,
                                    bool instanced) {
  if (vertex_colours) return VertexColourShader(device, shading, instanced);
  switch (shading) {
    case Shading::kFlat:
      return instanced ? CreateShaderModule(device, lit_flat_instanced_vert_spv)
                       : CreateShaderModule(device, lit_flat_vert_spv);
    case Shading::kGouraud:
      return instanced ? CreateShaderModule(device, lit_gouraud_instanced_vert_spv)
                       : CreateShaderModule(device, lit_gouraud_vert_spv);
    case Shading::kUnlit: break;
  }
  return instanced ? CreateShaderModule(device, triangle_instanced_vert_spv)
                   : CreateShaderModule(device, triangle_vert_spv);
}

// Unlit vertex colours are interpolated as Gouraud colours are: the same fragment shader.
vk::raii::ShaderModule FragmentShader(const vk::raii::Device& device, Shading shading, bool vertex_colours) {
  switch (shading) {
    case Shading::kFlat: return CreateShaderModule(device, lit_flat_frag_spv);
    case Shading::kGouraud: return CreateShaderModule(device, lit_gouraud_frag_spv);
    case Shading::kUnlit: break;
  }
  return vertex_colours ? CreateShaderModule(device, lit_gouraud_frag_spv)
                        : CreateShaderModule(device, triangle_frag_spv);
}

struct VertexInput {
  std::vector<vk::VertexInputBindingDescription> bindings;
  std::vector<vk::VertexInputAttributeDescription> attributes;
};

// Binding 0: the vec3 position of a triangle's corner. Unlit, it is the only per-vertex attribute:
// colours come per triangle from the storage buffer, found from the corner's number. Binding 1,
// instanced only: F, one mat4 per instance, a column per location. Binding 2, lit only: the
// corner's normal (location 5). Binding 3, with vertex colours only: the corner's packed RGBA8
// vertex colour (location 6).
VertexInput VertexInputFor(bool instanced, bool lit, bool vertex_colours) {
  VertexInput input{
      .bindings = {{.binding = 0, .stride = sizeof(glm::vec3), .inputRate = vk::VertexInputRate::eVertex}},
      .attributes = {{.location = 0, .binding = 0, .format = vk::Format::eR32G32B32Sfloat, .offset = 0}},
  };
  if (instanced) {
    input.bindings.push_back({.binding = 1, .stride = sizeof(glm::mat4), .inputRate = vk::VertexInputRate::eInstance});
    for (std::uint32_t column = 0; column < 4; ++column) {
      input.attributes.push_back({.location = 1 + column,
                                  .binding = 1,
                                  .format = vk::Format::eR32G32B32A32Sfloat,
                                  .offset = column * static_cast<std::uint32_t>(sizeof(glm::vec4))});
    }
  }
  if (lit) {
    input.bindings.push_back({.binding = 2, .stride = sizeof(glm::vec3), .inputRate = vk::VertexInputRate::eVertex});
    input.attributes.push_back({.location = 5, .binding = 2, .format = vk::Format::eR32G32B32Sfloat, .offset = 0});
  }
  if (vertex_colours) {
    input.bindings.push_back(
        {.binding = 3, .stride = sizeof(std::uint32_t), .inputRate = vk::VertexInputRate::eVertex});
    input.attributes.push_back({.location = 6, .binding = 3, .format = vk::Format::eR32Uint, .offset = 0});
  }
  return input;
}

}  // namespace

Pipeline::Pipeline(const vk::raii::Device& device) : device_(&device) {
  for (int i = 0; i < 3 * 2 * 2 * 2 * 2; ++i) pipelines_.emplace_back(nullptr);
  render_pass_ = CreateRenderPass(device);

  const vk::DescriptorSetLayoutBinding colour_binding{
      .binding = 0,
      .descriptorType = vk::DescriptorType::eStorageBuffer,
      .descriptorCount = 1,
      .stageFlags = vk::ShaderStageFlagBits::eFragment,
  };
  colour_set_layout_ = vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = 1, .pBindings = &colour_binding});

  const auto make_layout = [&](vk::DescriptorSetLayout set_layout, std::uint32_t push_bytes) {
    const vk::PushConstantRange push_range{
        .stageFlags = vk::ShaderStageFlagBits::eVertex, .offset = 0, .size = push_bytes};
    return vk::raii::PipelineLayout(device, vk::PipelineLayoutCreateInfo{
                                                .setLayoutCount = 1,
                                                .pSetLayouts = &set_layout,
                                                .pushConstantRangeCount = 1,
                                                .pPushConstantRanges = &push_range,
                                            });
  };
  // F, for the vertex shader (read on the per-draw path only).
  layout_ = make_layout(*colour_set_layout_, sizeof(PushConstants));

  // The lit shaders read everything in the vertex stage; the LitInstances (binding 1) through a
  // dynamic offset, one range of kLitInstancesPerRange draws at a time (light_buffers.hpp).
  std::array<vk::DescriptorSetLayoutBinding, 3> lit_bindings{};
  for (std::uint32_t b = 0; b < lit_bindings.size(); ++b) {
    lit_bindings[b] = {
        .binding = b,
        .descriptorType = b == 1 ? vk::DescriptorType::eStorageBufferDynamic : vk::DescriptorType::eStorageBuffer,
        .descriptorCount = 1,
        .stageFlags = vk::ShaderStageFlagBits::eVertex};
  }
  lit_set_layout_ = vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = lit_bindings.size(), .pBindings = lit_bindings.data()});
  lit_layout_ = make_layout(*lit_set_layout_, sizeof(LitPushConstants));
}

const vk::raii::Pipeline& Pipeline::pipeline(Shading shading, bool vertex_colours, FSource source, bool reversed_z,
                                             bool wireframe) {
  if (shading != Shading::kUnlit && wireframe) throw std::logic_error("wireframe edges are not lit");
  if (vertex_colours && wireframe) throw std::logic_error("wireframe edges take the triangle colours");
  std::size_t index = static_cast<std::size_t>(shading);
  for (const bool bit : {vertex_colours, source == FSource::kInstanceAttribute, reversed_z, wireframe})
    index = index * 2 + (bit ? 1 : 0);
  vk::raii::Pipeline& slot = pipelines_[index];
  if (!*slot) slot = Create(shading, vertex_colours, source, reversed_z, wireframe);
  return slot;
}

vk::raii::Pipeline Pipeline::Create(Shading shading, bool vertex_colours, FSource source, bool reversed_z,
                                    bool wireframe) const {
  const vk::raii::Device& device = *device_;
  const bool instanced = source == FSource::kInstanceAttribute;
  const bool lit = shading != Shading::kUnlit;
  const vk::raii::ShaderModule vertex = VertexShader(device, shading, vertex_colours, instanced);
  const vk::raii::ShaderModule fragment = FragmentShader(device, shading, vertex_colours);
  const std::array stages = {
      vk::PipelineShaderStageCreateInfo{.stage = vk::ShaderStageFlagBits::eVertex, .module = *vertex, .pName = "main"},
      vk::PipelineShaderStageCreateInfo{
          .stage = vk::ShaderStageFlagBits::eFragment, .module = *fragment, .pName = "main"},
  };

  const VertexInput input = VertexInputFor(instanced, lit, vertex_colours);
  const vk::PipelineVertexInputStateCreateInfo vertex_input{
      .vertexBindingDescriptionCount = static_cast<std::uint32_t>(input.bindings.size()),
      .pVertexBindingDescriptions = input.bindings.data(),
      .vertexAttributeDescriptionCount = static_cast<std::uint32_t>(input.attributes.size()),
      .pVertexAttributeDescriptions = input.attributes.data(),
  };
  const vk::PipelineInputAssemblyStateCreateInfo input_assembly{.topology = vk::PrimitiveTopology::eTriangleList};
  // Viewport and scissor are dynamic so one pipeline serves every image size.
  const vk::PipelineViewportStateCreateInfo viewport{.viewportCount = 1, .scissorCount = 1};
  const vk::PipelineRasterizationStateCreateInfo rasterization{
      .depthClampEnable = VK_FALSE,
      .rasterizerDiscardEnable = VK_FALSE,
      .polygonMode = wireframe ? vk::PolygonMode::eLine : vk::PolygonMode::eFill,
      .cullMode = vk::CullModeFlagBits::eNone,  // the chapter draws both sides
      .frontFace = vk::FrontFace::eCounterClockwise,
      .depthBiasEnable = VK_FALSE,
      .lineWidth = 1.0f,
  };
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples = vk::SampleCountFlagBits::e1};
  const vk::PipelineColorBlendAttachmentState blend_attachment{
      .blendEnable = VK_FALSE,
      .colorWriteMask = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                        vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA,
  };
  const vk::PipelineColorBlendStateCreateInfo colour_blend{.attachmentCount = 1, .pAttachments = &blend_attachment};
  const std::array dynamic_states = {vk::DynamicState::eViewport, vk::DynamicState::eScissor};
  const vk::PipelineDynamicStateCreateInfo dynamic{.dynamicStateCount = dynamic_states.size(),
                                                   .pDynamicStates = dynamic_states.data()};

  // The compare op is strict either way (LESS, or GREATER for reversed Z), so of two fragments
  // at equal depth the earlier draw stays, and a fragment exactly at the clear value is hidden.
  const vk::PipelineDepthStencilStateCreateInfo depth_stencil{
      .depthTestEnable = VK_TRUE,
      .depthWriteEnable = VK_TRUE,
      .depthCompareOp = reversed_z ? vk::CompareOp::eGreater : vk::CompareOp::eLess,
  };
  return vk::raii::Pipeline(device, nullptr,
                            vk::GraphicsPipelineCreateInfo{
                                .stageCount = stages.size(),
                                .pStages = stages.data(),
                                .pVertexInputState = &vertex_input,
                                .pInputAssemblyState = &input_assembly,
                                .pViewportState = &viewport,
                                .pRasterizationState = &rasterization,
                                .pMultisampleState = &multisample,
                                .pDepthStencilState = &depth_stencil,
                                .pColorBlendState = &colour_blend,
                                .pDynamicState = &dynamic,
                                .layout = *layout(lit),
                                .renderPass = *render_pass_,
                                .subpass = 0,
                            });
}

}  // namespace twinraster::gpu
