// The Vulkan renderer: draws a DrawList offscreen on lavapipe (or another device) and reads the
// pixels back.
#pragma once

#include "chain/draw_list.hpp"
#include "gpu/draw_batches.hpp"
#include "image/image.hpp"

#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace twinraster::gpu {

struct GpuOptions {
  // Empty: prefer lavapipe (llvmpipe / CPU device type); else a substring of the device name to
  // pick (case-insensitive).
  std::string device;
  // Enable VK_LAYER_KHRONOS_validation with synchronization validation; collect every message.
  bool validation = false;
  // How F reaches the vertex shader (gpu/draw_batches.hpp): per draw, per instance, or chosen
  // per run of instances. Every choice gives the same pixels.
  Instancing instancing = Instancing::kAuto;
  // F matrices per instance buffer; smaller values only serve tests of the splitting.
  std::uint32_t instances_per_buffer = kInstancesPerBuffer;
};

// Per Render(): setup = buffers/upload/command recording, draw = submit+wait, readback = map+copy
// into Image.
struct GpuTimings {
  double setup_ms = 0, draw_ms = 0, readback_ms = 0;
  std::size_t draw_commands = 0;    // vkCmdDraw calls recorded
  std::size_t instanced_draws = 0;  // draws of the list that were drawn instanced
};

// Who drew the image: what the twin needs to pick its rules (which Mesa, which vector width), and
// what a report names. From vkGetPhysicalDeviceProperties2 with VkPhysicalDeviceDriverProperties;
// the driver fields stay empty on a device older than Vulkan 1.2 without VK_KHR_driver_properties.
struct DeviceIdentity {
  std::string name;         // deviceName, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string driver_name;  // driverName, e.g. "llvmpipe"
  std::string driver_info;  // driverInfo, e.g. "Mesa 22.3.6 (LLVM 15.0.6)"
  std::uint32_t vendor_id = 0, device_id = 0, driver_id = 0, driver_version = 0, api_version = 0;
  std::uint32_t subpixel_bits = 0;  // limits.subPixelPrecisionBits
  bool strict_lines = false;        // limits.strictLines
  // twinraster never sets VK_EXT_line_rasterization state, so lines are drawn in the device's
  // default mode.
  std::string line_rasterization = "default";
};

// No usable Vulkan device, or the validation layer is missing; the message says what to install.
class GpuUnavailable : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Whether this build has the Vulkan renderer: false when configured with -DTWINRASTER_VULKAN=OFF,
// where every GpuRenderer (and ListDevices) throws GpuUnavailable saying so (gpu/no_vulkan.cpp).
bool VulkanInBuild();

class GpuRenderer {
 public:
  // Creates the instance, device and pipelines; throws GpuUnavailable.
  explicit GpuRenderer(const GpuOptions& options = {});
  ~GpuRenderer();
  GpuRenderer(GpuRenderer&&) noexcept;
  GpuRenderer& operator=(GpuRenderer&&) noexcept;
  GpuRenderer(const GpuRenderer&) = delete;
  GpuRenderer& operator=(const GpuRenderer&) = delete;

  // May be called many times with different sizes. Throws std::invalid_argument for a malformed
  // list (size 0 or beyond the device's limit, an index or mesh out of range, a colour missing).
  Image Render(const DrawList& list, GpuTimings* timings = nullptr);

  std::string DeviceName() const;
  const DeviceIdentity& Device() const;

  // Every message the validation layer's debug messenger received (warnings and errors, including
  // synchronization validation); always empty without GpuOptions::validation.
  const std::vector<std::string>& ValidationMessages() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;  // pImpl: keeps vulkan.hpp out of every file that includes this one
};

}  // namespace twinraster::gpu
