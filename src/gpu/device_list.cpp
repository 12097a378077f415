#include "gpu/device_list.hpp"

#include "gpu/driver_files.hpp"
#include "gpu/keep_loaded.hpp"
#include "gpu/vulkan_context.hpp"

#include <string_view>

namespace twinraster::gpu {
namespace {

bool DeviceHasExtension(const vk::raii::PhysicalDevice& device, std::string_view name) {
  for (const vk::ExtensionProperties& e : device.enumerateDeviceExtensionProperties()) {
    if (name == e.extensionName.data()) return true;
  }
  return false;
}

// No layers or extensions; 1.1 as VulkanContext asks, for vkGetPhysicalDeviceProperties2.
vk::raii::Instance BareInstance(const vk::raii::Context& context) {
  const vk::ApplicationInfo app_info{.pApplicationName = "twinraster", .apiVersion = VK_API_VERSION_1_1};
  try {
    return vk::raii::Instance(context, vk::InstanceCreateInfo{.pApplicationInfo = &app_info});
  } catch (const vk::SystemError& error) {
    throw GpuUnavailable(std::string(error.what()) +
                         "; install a Vulkan driver, e.g. `apt-get install mesa-vulkan-drivers` for lavapipe");
  }
}

}  // namespace

DeviceIdentity Identify(const vk::raii::PhysicalDevice& device, const vk::PhysicalDeviceProperties& p) {
  DeviceIdentity id;
  id.name = p.deviceName.data();
  id.vendor_id = p.vendorID, id.device_id = p.deviceID, id.driver_version = p.driverVersion;
  id.api_version = p.apiVersion;
  id.subpixel_bits = p.limits.subPixelPrecisionBits;
  id.strict_lines = p.limits.strictLines == VK_TRUE;
  // VkPhysicalDeviceDriverProperties is core from Vulkan 1.2, an extension before it.
  if (VK_API_VERSION_MINOR(p.apiVersion) >= 2 || VK_API_VERSION_MAJOR(p.apiVersion) > 1 ||
      DeviceHasExtension(device, VK_KHR_DRIVER_PROPERTIES_EXTENSION_NAME)) {
    const auto chain = device.getProperties2<vk::PhysicalDeviceProperties2, vk::PhysicalDeviceDriverProperties>();
    const auto& driver = chain.get<vk::PhysicalDeviceDriverProperties>();
    id.driver_name = driver.driverName.data();
    id.driver_info = driver.driverInfo.data();
    id.driver_id = static_cast<std::uint32_t>(driver.driverID);
  }
  return id;
}

std::vector<DeviceIdentity> ListDevices() {
  const ExtraDriverOffer offer;
  const vk::raii::Context context(&vkGetInstanceProcAddr);
  const vk::raii::Instance instance = BareInstance(context);
  try {
    std::vector<DeviceIdentity> devices;
    for (const vk::raii::PhysicalDevice& device : instance.enumeratePhysicalDevices()) {
      devices.push_back(Identify(device, device.getProperties()));
    }
    KeepVulkanLibrariesLoaded();  // sanitizer builds only: see keep_loaded.hpp
    return devices;
  } catch (const vk::SystemError& error) {
    throw GpuUnavailable(error.what());
  }
}

std::string VulkanVersionText(std::uint32_t version) {
  return std::to_string(VK_API_VERSION_MAJOR(version)) + "." + std::to_string(VK_API_VERSION_MINOR(version)) + "." +
         std::to_string(VK_API_VERSION_PATCH(version));
}

}  // namespace twinraster::gpu
