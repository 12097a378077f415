// The Vulkan instance, the optional validation messenger, the chosen device and its graphics
// queue: everything that lives exactly as long as one GpuRenderer.
#pragma once

#include "gpu/gpu_renderer.hpp"

#include <vulkan/vulkan_raii.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace twinraster::gpu {

// What a renderer on `device` reports of it (`properties` is its getProperties()). Defined in
// device_list.cpp, which lists devices by it too.
DeviceIdentity Identify(const vk::raii::PhysicalDevice& device, const vk::PhysicalDeviceProperties& properties);

class VulkanContext {
 public:
  explicit VulkanContext(const GpuOptions& options);  // throws GpuUnavailable
  VulkanContext(const VulkanContext&) = delete;
  VulkanContext& operator=(const VulkanContext&) = delete;

  const vk::raii::Device& device() const { return device_; }
  const vk::raii::Queue& queue() const { return queue_; }
  std::uint32_t queue_family() const { return queue_family_; }
  const vk::PhysicalDeviceLimits& limits() const { return properties_.limits; }
  std::string device_name() const { return properties_.deviceName; }
  const DeviceIdentity& identity() const { return identity_; }
  const std::vector<std::string>& messages() const { return messages_; }
  bool wireframe() const { return wireframe_; }  // polygonMode LINE (fillModeNonSolid) enabled

  // A memory type allowed by `type_bits` (from vkGet*MemoryRequirements) that has every `required`
  // flag, preferring one that also has every `preferred` flag.
  std::uint32_t FindMemoryType(std::uint32_t type_bits, vk::MemoryPropertyFlags required,
                               vk::MemoryPropertyFlags preferred = {}) const;

 private:
  bool ChooseLavapipeAlone(bool validation, const std::string& wanted);  // loading lavapipe's driver only
  void CreateInstance(bool validation);  // with the validation layer and its messenger if asked
  void ChooseDevice(const std::string& wanted);
  void CreateDevice();  // and its queue

  // Declared first so it outlives the instance: the layer reports until vkDestroyInstance returns.
  std::vector<std::string> messages_;
  vk::raii::Context context_;
  vk::raii::Instance instance_ = nullptr;
  vk::raii::DebugUtilsMessengerEXT messenger_ = nullptr;
  vk::raii::PhysicalDevice physical_device_ = nullptr;
  vk::PhysicalDeviceProperties properties_;
  vk::PhysicalDeviceMemoryProperties memory_properties_;
  std::uint32_t queue_family_ = 0;
  vk::raii::Device device_ = nullptr;
  vk::raii::Queue queue_ = nullptr;
  bool wireframe_ = false;
  DeviceIdentity identity_;
};

}  // namespace twinraster::gpu
