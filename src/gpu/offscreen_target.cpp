#include "gpu/offscreen_target.hpp"

#include "gpu/pipeline.hpp"

#include <array>

namespace twinraster::gpu {
namespace {

AttachmentImage CreateAttachment(const VulkanContext& context, vk::Format format, vk::ImageUsageFlags usage,
                                 vk::ImageAspectFlags aspect, std::uint32_t width, std::uint32_t height) {
  const vk::raii::Device& device = context.device();
  AttachmentImage result;
  result.image = vk::raii::Image(device, vk::ImageCreateInfo{
                                             .imageType = vk::ImageType::e2D,
                                             .format = format,
                                             .extent = {width, height, 1},
                                             .mipLevels = 1,
                                             .arrayLayers = 1,
                                             .samples = vk::SampleCountFlagBits::e1,
                                             .tiling = vk::ImageTiling::eOptimal,
                                             .usage = usage,
                                             .sharingMode = vk::SharingMode::eExclusive,
                                             .initialLayout = vk::ImageLayout::eUndefined,
                                         });
  const vk::MemoryRequirements requirements = result.image.getMemoryRequirements();
  result.memory =
      vk::raii::DeviceMemory(device, vk::MemoryAllocateInfo{
                                         .allocationSize = requirements.size,
                                         .memoryTypeIndex = context.FindMemoryType(
                                             requirements.memoryTypeBits, {}, vk::MemoryPropertyFlagBits::eDeviceLocal),
                                     });
  result.image.bindMemory(*result.memory, 0);
  result.view = vk::raii::ImageView(device, vk::ImageViewCreateInfo{
                                                .image = *result.image,
                                                .viewType = vk::ImageViewType::e2D,
                                                .format = format,
                                                .subresourceRange = {aspect, 0, 1, 0, 1},
                                            });
  return result;
}

}  // namespace

OffscreenTarget::OffscreenTarget(const VulkanContext& context, const vk::raii::RenderPass& render_pass,
                                 std::uint32_t width, std::uint32_t height)
    : width_(width),
      height_(height),
      colour_(CreateAttachment(context, kColourFormat,
                               vk::ImageUsageFlagBits::eColorAttachment | vk::ImageUsageFlagBits::eTransferSrc,
                               vk::ImageAspectFlagBits::eColor, width, height)),
      depth_(CreateAttachment(context, kDepthFormat, vk::ImageUsageFlagBits::eDepthStencilAttachment,
                              vk::ImageAspectFlagBits::eDepth, width, height)),
      readback_(context, vk::DeviceSize{width} * height * 4, vk::BufferUsageFlagBits::eTransferDst) {
  const std::array views = {*colour_.view, *depth_.view};
  framebuffer_ = vk::raii::Framebuffer(context.device(), vk::FramebufferCreateInfo{
                                                             .renderPass = *render_pass,
                                                             .attachmentCount = views.size(),
                                                             .pAttachments = views.data(),
                                                             .width = width,
                                                             .height = height,
                                                             .layers = 1,
                                                         });
}

}  // namespace twinraster::gpu
