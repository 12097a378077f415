#include "gpu/gpu_renderer.hpp"

#include "base/stopwatch.hpp"
#include "gpu/draw_recorder.hpp"
#include "gpu/instance_buffers.hpp"
#include "gpu/light_buffers.hpp"
#include "gpu/mesh_buffers.hpp"
#include "gpu/offscreen_target.hpp"
#include "gpu/pipeline.hpp"
#include "gpu/vulkan_context.hpp"

#include <algorithm>
#include <array>
#include <cstring>
#include <limits>
#include <optional>
#include <string>

namespace twinraster::gpu {
namespace {

void CheckSize(std::uint32_t width, std::uint32_t height, const vk::PhysicalDeviceLimits& limits) {
  const std::uint32_t max_width =
      std::min({limits.maxImageDimension2D, limits.maxFramebufferWidth, limits.maxViewportDimensions[0]});
  const std::uint32_t max_height =
      std::min({limits.maxImageDimension2D, limits.maxFramebufferHeight, limits.maxViewportDimensions[1]});
  if (width == 0 || height == 0 || width > max_width || height > max_height) {
    throw std::invalid_argument("cannot render " + std::to_string(width) + "x" + std::to_string(height) +
                                " pixels: the device allows 1x1 to " + std::to_string(max_width) + "x" +
                                std::to_string(max_height));
  }
}

// The clear colour as the shader-side float k / 255: converting back to UNORM8 gives k exactly.
vk::ClearValue ClearColour(Rgb8 background) {
  const auto unorm = [](std::uint8_t k) { return static_cast<float>(k) / 255.0f; };
  return vk::ClearValue{.color = vk::ClearColorValue{.float32 = std::array{unorm(background.r), unorm(background.g),
                                                                           unorm(background.b), 1.0f}}};
}

}  // namespace

struct GpuRenderer::Impl {
  explicit Impl(const GpuOptions& options);
  Image Render(const DrawList& list, GpuTimings* timings);
  // Returns the number of draw commands recorded.
  std::size_t Record(const DrawList& list, const DrawPlan& plan, const MeshBuffers& meshes,
                     const InstanceBuffers& instances, const LightBuffers* lights);
  // Points the descriptor sets at this frame's colour buffer and, when lit, its light buffers.
  void PointSets(const MeshBuffers& meshes, const LightBuffers* lights);
  void BeginPass(const DrawList& list);
  void CopyOut(const DrawList& list);

  Instancing instancing;
  std::uint32_t instances_per_buffer;
  // Members are destroyed in reverse order: everything below goes before the device in `context`.
  VulkanContext context;
  Pipeline pipeline;
  vk::raii::DescriptorPool descriptor_pool = nullptr;
  vk::raii::DescriptorSet colour_set = nullptr;  // re-pointed at each Render()'s colour buffer
  vk::raii::DescriptorSet lit_set = nullptr;     // the same, and the light buffers, for lit draws
  vk::raii::CommandPool command_pool = nullptr;
  vk::raii::CommandBuffer commands = nullptr;  // re-recorded by each Render()
  vk::raii::Fence done = nullptr;              // signalled when the frame has been copied out
  std::unique_ptr<OffscreenTarget> target;     // kept while the image size stays the same
};

GpuRenderer::Impl::Impl(const GpuOptions& options)
    : instancing(options.instancing),
      instances_per_buffer(options.instances_per_buffer),
      context(options),
      pipeline(context.device()) {
  const vk::raii::Device& device = context.device();
  // The unlit set's one storage buffer and the lit set's three (one with a dynamic offset).
  const std::array pool_sizes = {
      vk::DescriptorPoolSize{.type = vk::DescriptorType::eStorageBuffer, .descriptorCount = 3},
      vk::DescriptorPoolSize{.type = vk::DescriptorType::eStorageBufferDynamic, .descriptorCount = 1}};
  descriptor_pool = vk::raii::DescriptorPool(device, vk::DescriptorPoolCreateInfo{
                                                         // vk::raii::DescriptorSet frees itself, which needs this flag.
                                                         .flags = vk::DescriptorPoolCreateFlagBits::eFreeDescriptorSet,
                                                         .maxSets = 2,
                                                         .poolSizeCount = pool_sizes.size(),
                                                         .pPoolSizes = pool_sizes.data(),
                                                     });
  const std::array set_layouts = {*pipeline.set_layout(false), *pipeline.set_layout(true)};
  const vk::DescriptorSetAllocateInfo set_info{
      .descriptorPool = *descriptor_pool,
      .descriptorSetCount = set_layouts.size(),
      .pSetLayouts = set_layouts.data(),
  };
  std::vector<vk::raii::DescriptorSet> sets = device.allocateDescriptorSets(set_info);
  colour_set = std::move(sets[0]);
  lit_set = std::move(sets[1]);

  command_pool = vk::raii::CommandPool(device, vk::CommandPoolCreateInfo{
                                                   .flags = vk::CommandPoolCreateFlagBits::eResetCommandBuffer,
                                                   .queueFamilyIndex = context.queue_family(),
                                               });
  const vk::CommandBufferAllocateInfo command_info{
      .commandPool = *command_pool,
      .level = vk::CommandBufferLevel::ePrimary,
      .commandBufferCount = 1,
  };
  commands = std::move(device.allocateCommandBuffers(command_info).front());
  done = vk::raii::Fence(device, vk::FenceCreateInfo{});
}

Image GpuRenderer::Impl::Render(const DrawList& list, GpuTimings* timings) {
  Stopwatch clock;

  // Setup. Check and upload first: a malformed list then throws before anything is touched.
  CheckSize(list.width, list.height, context.limits());
  if (list.wireframe && !context.wireframe()) {
    throw GpuUnavailable(context.device_name() +
                         " cannot draw wireframes (no fillModeNonSolid feature); "
                         "--backend cpu can");
  }
  const MeshBuffers meshes(context, list);  // must live until the fence has signalled
  const DrawPlan plan = PlanDraws(list, instancing, instances_per_buffer);
  const InstanceBuffers instances(context, list, plan);  // likewise
  std::optional<LightBuffers> lights;                    // likewise
  if (list.lighting) lights.emplace(context, list);
  if (!target || target->width() != list.width || target->height() != list.height) {
    target.reset();  // free the old images first: at 16384x16384 one target holds 3 GiB
    target = std::make_unique<OffscreenTarget>(context, pipeline.render_pass(), list.width, list.height);
  }
  PointSets(meshes, lights ? &*lights : nullptr);
  const std::size_t draw_commands = Record(list, plan, meshes, instances, lights ? &*lights : nullptr);
  const double setup_ms = clock.Lap();

  // Draw: run the commands and wait for them.
  context.device().resetFences(*done);
  const vk::CommandBuffer command_buffer = *commands;
  context.queue().submit(vk::SubmitInfo{.commandBufferCount = 1, .pCommandBuffers = &command_buffer}, *done);
  if (context.device().waitForFences(*done, VK_TRUE, std::numeric_limits<std::uint64_t>::max()) !=
      vk::Result::eSuccess) {
    throw std::runtime_error("the Vulkan device did not finish the frame");
  }
  const double draw_ms = clock.Lap();

  // The readback buffer holds tightly packed RGBA rows, top row first: exactly Image's layout.
  Image image(list.width, list.height);
  std::memcpy(image.rgba.data(), target->readback().data(), image.rgba.size());
  const double readback_ms = clock.Lap();

  if (timings != nullptr) {
    std::size_t instanced = 0;
    for (const DrawBatch& batch : plan.batches) instanced += batch.instanced ? batch.count : 0;
    *timings = GpuTimings{.setup_ms = setup_ms,
                          .draw_ms = draw_ms,
                          .readback_ms = readback_ms,
                          .draw_commands = draw_commands,
                          .instanced_draws = instanced};
  }
  return image;
}

// Safe to rewrite: the previous frame that read the sets has finished (Render waited for it).
void GpuRenderer::Impl::PointSets(const MeshBuffers& meshes, const LightBuffers* lights) {
  const auto point = [&](const vk::raii::DescriptorSet& set, std::uint32_t binding, vk::Buffer buffer,
                         vk::DeviceSize range = VK_WHOLE_SIZE,
                         vk::DescriptorType type = vk::DescriptorType::eStorageBuffer) {
    const vk::DescriptorBufferInfo info{.buffer = buffer, .offset = 0, .range = range};
    context.device().updateDescriptorSets(
        vk::WriteDescriptorSet{
            .dstSet = *set, .dstBinding = binding, .descriptorCount = 1, .descriptorType = type, .pBufferInfo = &info},
        nullptr);
  };
  point(colour_set, 0, meshes.colours());
  if (lights) {
    point(lit_set, 0, meshes.colours());
    point(lit_set, 1, lights->instances(), lights->instance_range(), vk::DescriptorType::eStorageBufferDynamic);
    point(lit_set, 2, lights->lights());
  }
}

std::size_t GpuRenderer::Impl::Record(const DrawList& list, const DrawPlan& plan, const MeshBuffers& meshes,
                                      const InstanceBuffers& instances, const LightBuffers* lights) {
  const vk::raii::CommandBuffer& cmd = commands;
  cmd.reset();  // a Render() that threw halfway may have left it in the recording state
  cmd.begin(vk::CommandBufferBeginInfo{.flags = vk::CommandBufferUsageFlagBits::eOneTimeSubmit});
  BeginPass(list);
  cmd.bindVertexBuffers(0, meshes.corners(), vk::DeviceSize{0});
  if (lights) cmd.bindVertexBuffers(2, lights->normals(), vk::DeviceSize{0});
  if (meshes.vertex_colours()) cmd.bindVertexBuffers(3, meshes.vertex_colours()->buffer(), vk::DeviceSize{0});
  DrawRecorder recorder(cmd, pipeline, list, meshes, instances, *colour_set, *lit_set);
  for (const DrawBatch& batch : plan.batches) recorder.Record(batch);
  cmd.endRenderPass();  // the render pass's last dependency orders the copy after the drawing
  CopyOut(list);
  cmd.end();
  return recorder.draw_commands();
}

// Clears colour and depth (depth to the far end: 1.0, or 0.0 with reversed Z) and sets the
// viewport and scissor to the whole image.
void GpuRenderer::Impl::BeginPass(const DrawList& list) {
  const vk::raii::CommandBuffer& cmd = commands;
  const vk::Extent2D extent{list.width, list.height};
  const float far_depth = list.reversed_z ? 0.0f : 1.0f;
  const std::array clear_values = {ClearColour(list.background),
                                   vk::ClearValue{.depthStencil = {.depth = far_depth, .stencil = 0}}};
  cmd.beginRenderPass(
      vk::RenderPassBeginInfo{
          .renderPass = *pipeline.render_pass(),
          .framebuffer = target->framebuffer(),
          .renderArea = {.offset = {0, 0}, .extent = extent},
          .clearValueCount = clear_values.size(),
          .pClearValues = clear_values.data(),
      },
      vk::SubpassContents::eInline);
  cmd.setViewport(0, vk::Viewport{.x = 0.0f,
                                  .y = 0.0f,
                                  .width = static_cast<float>(list.width),
                                  .height = static_cast<float>(list.height),
                                  .minDepth = 0.0f,
                                  .maxDepth = 1.0f});
  cmd.setScissor(0, vk::Rect2D{.offset = {0, 0}, .extent = extent});
}

// Copies the colour image into the readback buffer, visible to the host once the fence says the
// work is done.
void GpuRenderer::Impl::CopyOut(const DrawList& list) {
  const vk::raii::CommandBuffer& cmd = commands;
  cmd.copyImageToBuffer(target->colour_image(), vk::ImageLayout::eTransferSrcOptimal, target->readback().buffer(),
                        vk::BufferImageCopy{
                            .bufferOffset = 0,
                            .bufferRowLength = 0,  // 0: rows tightly packed
                            .bufferImageHeight = 0,
                            .imageSubresource = {.aspectMask = vk::ImageAspectFlagBits::eColor,
                                                 .mipLevel = 0,
                                                 .baseArrayLayer = 0,
                                                 .layerCount = 1},
                            .imageOffset = {0, 0, 0},
                            .imageExtent = {list.width, list.height, 1},
                        });
  cmd.pipelineBarrier(vk::PipelineStageFlagBits::eTransfer, vk::PipelineStageFlagBits::eHost, {}, nullptr,
                      vk::BufferMemoryBarrier{
                          .srcAccessMask = vk::AccessFlagBits::eTransferWrite,
                          .dstAccessMask = vk::AccessFlagBits::eHostRead,
                          .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                          .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                          .buffer = target->readback().buffer(),
                          .offset = 0,
                          .size = VK_WHOLE_SIZE,
                      },
                      nullptr);
}

bool VulkanInBuild() { return true; }

GpuRenderer::GpuRenderer(const GpuOptions& options) : impl_(std::make_unique<Impl>(options)) {}
GpuRenderer::~GpuRenderer() = default;
GpuRenderer::GpuRenderer(GpuRenderer&&) noexcept = default;
GpuRenderer& GpuRenderer::operator=(GpuRenderer&&) noexcept = default;

Image GpuRenderer::Render(const DrawList& list, GpuTimings* timings) {
  if (!impl_) throw std::logic_error("GpuRenderer::Render on a moved-from renderer");
  return impl_->Render(list, timings);
}

std::string GpuRenderer::DeviceName() const { return impl_ ? impl_->context.device_name() : ""; }

const DeviceIdentity& GpuRenderer::Device() const {
  static const DeviceIdentity none;
  return impl_ ? impl_->context.identity() : none;
}

const std::vector<std::string>& GpuRenderer::ValidationMessages() const {
  static const std::vector<std::string> none;
  return impl_ ? impl_->context.messages() : none;
}

}  // namespace twinraster::gpu
