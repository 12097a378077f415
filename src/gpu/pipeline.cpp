#include "gpu/pipeline.hpp"

#include "shaders/triangle.frag.h"
#include "shaders/triangle.vert.h"
#include "shaders/triangle_instanced.vert.h"

#include <array>

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
          .srcStageMask =
              vk::PipelineStageFlagBits::eTransfer | vk::PipelineStageFlagBits::eLateFragmentTests,
          .dstStageMask = vk::PipelineStageFlagBits::eColorAttachmentOutput |
                          vk::PipelineStageFlagBits::eEarlyFragmentTests |
                          vk::PipelineStageFlagBits::eLateFragmentTests,
          .srcAccessMask = vk::AccessFlagBits::eDepthStencilAttachmentWrite,
          .dstAccessMask = vk::AccessFlagBits::eColorAttachmentWrite |
                           vk::AccessFlagBits::eDepthStencilAttachmentRead |
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

vk::raii::ShaderModule CreateShaderModule(const vk::raii::Device& device,
                                          const std::uint32_t* words, std::size_t bytes) {
  return vk::raii::ShaderModule(device,
                                vk::ShaderModuleCreateInfo{.codeSize = bytes, .pCode = words});
}

}  // namespace

Pipeline::Pipeline(const vk::raii::Device& device) : device_(&device) {
  render_pass_ = CreateRenderPass(device);

  const vk::DescriptorSetLayoutBinding colour_binding{
      .binding = 0,
      .descriptorType = vk::DescriptorType::eStorageBuffer,
      .descriptorCount = 1,
      .stageFlags = vk::ShaderStageFlagBits::eFragment,
  };
  colour_set_layout_ = vk::raii::DescriptorSetLayout(
      device, vk::DescriptorSetLayoutCreateInfo{.bindingCount = 1, .pBindings = &colour_binding});

  // F, for the vertex shader (read on the per-draw path only).
  const vk::PushConstantRange push_range{
      .stageFlags = vk::ShaderStageFlagBits::eVertex,
      .offset = 0,
      .size = sizeof(PushConstants),
  };
  const vk::DescriptorSetLayout set_layout = *colour_set_layout_;
  layout_ = vk::raii::PipelineLayout(device, vk::PipelineLayoutCreateInfo{
                                                 .setLayoutCount = 1,
                                                 .pSetLayouts = &set_layout,
                                                 .pushConstantRangeCount = 1,
                                                 .pPushConstantRanges = &push_range,
                                             });
}

const vk::raii::Pipeline& Pipeline::pipeline(FSource source, bool reversed_z, bool wireframe) {
  vk::raii::Pipeline& slot =
      pipelines_[source == FSource::kInstanceAttribute ? 1 : 0][reversed_z ? 1 : 0][wireframe ? 1 : 0];
  if (!*slot) slot = Create(source, reversed_z, wireframe);
  return slot;
}

vk::raii::Pipeline Pipeline::Create(FSource source, bool reversed_z, bool wireframe) const {
  const vk::raii::Device& device = *device_;
  const bool instanced = source == FSource::kInstanceAttribute;
  const vk::raii::ShaderModule vertex =
      instanced ? CreateShaderModule(device, triangle_instanced_vert_spv, sizeof(triangle_instanced_vert_spv))
                : CreateShaderModule(device, triangle_vert_spv, sizeof(triangle_vert_spv));
  const vk::raii::ShaderModule fragment =
      CreateShaderModule(device, triangle_frag_spv, sizeof(triangle_frag_spv));
  const std::array stages = {
      vk::PipelineShaderStageCreateInfo{
          .stage = vk::ShaderStageFlagBits::eVertex, .module = *vertex, .pName = "main"},
      vk::PipelineShaderStageCreateInfo{
          .stage = vk::ShaderStageFlagBits::eFragment, .module = *fragment, .pName = "main"},
  };

  // Binding 0: the vec3 position of a triangle's corner, the only per-vertex attribute. Colours
  // come per triangle from the storage buffer, found from the corner's number. Binding 1,
  // instanced only: F, one mat4 per instance, a column per location.
  const std::array bindings = {
      vk::VertexInputBindingDescription{
          .binding = 0, .stride = 3 * sizeof(float), .inputRate = vk::VertexInputRate::eVertex},
      vk::VertexInputBindingDescription{
          .binding = 1, .stride = sizeof(glm::mat4), .inputRate = vk::VertexInputRate::eInstance},
  };
  std::array<vk::VertexInputAttributeDescription, 5> attributes{};
  attributes[0] = {.location = 0, .binding = 0, .format = vk::Format::eR32G32B32Sfloat, .offset = 0};
  for (std::uint32_t column = 0; column < 4; ++column) {
    attributes[1 + column] = {.location = 1 + column,
                              .binding = 1,
                              .format = vk::Format::eR32G32B32A32Sfloat,
                              .offset = column * static_cast<std::uint32_t>(sizeof(glm::vec4))};
  }
  const vk::PipelineVertexInputStateCreateInfo vertex_input{
      .vertexBindingDescriptionCount = instanced ? 2u : 1u,
      .pVertexBindingDescriptions = bindings.data(),
      .vertexAttributeDescriptionCount = instanced ? 5u : 1u,
      .pVertexAttributeDescriptions = attributes.data(),
  };
  const vk::PipelineInputAssemblyStateCreateInfo input_assembly{
      .topology = vk::PrimitiveTopology::eTriangleList};
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
  const vk::PipelineMultisampleStateCreateInfo multisample{.rasterizationSamples =
                                                               vk::SampleCountFlagBits::e1};
  const vk::PipelineColorBlendAttachmentState blend_attachment{
      .blendEnable = VK_FALSE,
      .colorWriteMask = vk::ColorComponentFlagBits::eR | vk::ColorComponentFlagBits::eG |
                        vk::ColorComponentFlagBits::eB | vk::ColorComponentFlagBits::eA,
  };
  const vk::PipelineColorBlendStateCreateInfo colour_blend{.attachmentCount = 1,
                                                           .pAttachments = &blend_attachment};
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
                                .layout = *layout_,
                                .renderPass = *render_pass_,
                                .subpass = 0,
                            });
}

}  // namespace twinraster::gpu
