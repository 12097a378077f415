// Every Vulkan device this process can reach, identified as a renderer on it would be (for
// --version). It creates no logical device and does not check that the renderer could use them.
#pragma once

#include "gpu/gpu_renderer.hpp"

#include <cstdint>
#include <string>
#include <vector>

namespace twinraster::gpu {

// The loader's devices plus those of the drivers an ExtraDriverOffer adds, in the loader's order. Throws
// GpuUnavailable when no Vulkan instance can be created (no loader or no driver).
std::vector<DeviceIdentity> ListDevices();

// A VkPhysicalDeviceProperties::apiVersion as "1.3.230".
std::string VulkanVersionText(std::uint32_t version);

}  // namespace twinraster::gpu
