// What one image size needs: the colour and depth images drawn into, their framebuffer, and the
// host buffer the colour image is copied to for reading.
#pragma once

#include "gpu/host_buffer.hpp"
#include "gpu/vulkan_context.hpp"

#include <cstdint>

namespace twinraster::gpu {

// An image with its own memory and a view of the whole of it. Declared in this order so that
// destruction goes view, image, then the memory the image was bound to.
struct AttachmentImage {
  vk::raii::DeviceMemory memory = nullptr;
  vk::raii::Image image = nullptr;
  vk::raii::ImageView view = nullptr;
};

class OffscreenTarget {
 public:
  OffscreenTarget(const VulkanContext& context, const vk::raii::RenderPass& render_pass, std::uint32_t width,
                  std::uint32_t height);

  std::uint32_t width() const { return width_; }
  std::uint32_t height() const { return height_; }
  vk::Image colour_image() const { return *colour_.image; }
  vk::Framebuffer framebuffer() const { return *framebuffer_; }
  const HostBuffer& readback() const { return readback_; }  // width * height * 4 bytes, rows top first

 private:
  std::uint32_t width_, height_;
  AttachmentImage colour_;
  AttachmentImage depth_;
  vk::raii::Framebuffer framebuffer_ = nullptr;
  HostBuffer readback_;
};

}  // namespace twinraster::gpu
