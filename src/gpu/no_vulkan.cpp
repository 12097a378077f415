// The GPU stage of a build configured with -DTWINRASTER_VULKAN=OFF, in place of gpu_renderer.cpp,
// device_list.cpp and driver_files.cpp: the same declarations, every way of reaching a device
// throws GpuUnavailable saying that this build has no Vulkan, and no driver file is offered to a
// loader that is not there. Everything that draws on the GPU (run/, bench/, cli/) then fails as it
// does on a machine without a driver (exit 3), and the rest works.
#include "gpu/device_list.hpp"
#include "gpu/driver_files.hpp"
#include "gpu/gpu_renderer.hpp"

namespace twinraster::gpu {
namespace {

[[noreturn]] void ThrowNoVulkan() {
  throw GpuUnavailable("this build has no Vulkan: it was configured with -DTWINRASTER_VULKAN=OFF");
}

}  // namespace

bool VulkanInBuild() { return false; }

// Never made: the constructor throws before a renderer exists.
struct GpuRenderer::Impl {};

GpuRenderer::GpuRenderer(const GpuOptions&) { ThrowNoVulkan(); }
GpuRenderer::~GpuRenderer() = default;
GpuRenderer::GpuRenderer(GpuRenderer&&) noexcept = default;
GpuRenderer& GpuRenderer::operator=(GpuRenderer&&) noexcept = default;

Image GpuRenderer::Render(const DrawList&, GpuTimings*) { ThrowNoVulkan(); }

std::string GpuRenderer::DeviceName() const { return ""; }

const DeviceIdentity& GpuRenderer::Device() const {
  static const DeviceIdentity none;
  return none;
}

const std::vector<std::string>& GpuRenderer::ValidationMessages() const {
  static const std::vector<std::string> none;
  return none;
}

std::vector<DeviceIdentity> ListDevices() { ThrowNoVulkan(); }

// VK_API_VERSION_MAJOR, _MINOR and _PATCH without vulkan.h: 7, 10 and 12 bits above the variant's 3.
std::string VulkanVersionText(std::uint32_t version) {
  return std::to_string(version >> 22 & 0x7Fu) + "." + std::to_string(version >> 12 & 0x3FFu) + "." +
         std::to_string(version & 0xFFFu);
}

// No loader to offer drivers to: files() and manifest() stay empty.
ExtraDriverOffer::ExtraDriverOffer(bool) {}
ExtraDriverOffer::~ExtraDriverOffer() = default;
LavapipeAlone::LavapipeAlone() = default;
LavapipeAlone::~LavapipeAlone() = default;

}  // namespace twinraster::gpu
