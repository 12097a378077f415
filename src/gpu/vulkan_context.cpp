#include "gpu/vulkan_context.hpp"

#include "base/device_names.hpp"
#include "gpu/driver_files.hpp"
#include "gpu/keep_loaded.hpp"

#include <algorithm>
#include <optional>
#include <string_view>

namespace twinraster::gpu {
namespace {

constexpr const char* kValidationLayer = "VK_LAYER_KHRONOS_validation";

// The debug messenger's callback: keep the message for ValidationMessages().
VKAPI_ATTR VkBool32 VKAPI_CALL StoreMessage(VkDebugUtilsMessageSeverityFlagBitsEXT severity,
                                            VkDebugUtilsMessageTypeFlagsEXT types,
                                            const VkDebugUtilsMessengerCallbackDataEXT* data, void* user_data) {
  // An exception must not unwind through the layer's C code; a lost message is the lesser harm.
  try {
    auto* messages = static_cast<std::vector<std::string>*>(user_data);
    messages->push_back(vk::to_string(vk::DebugUtilsMessageSeverityFlagBitsEXT(severity)) + " " +
                        vk::to_string(vk::DebugUtilsMessageTypeFlagsEXT(types)) + ": " +
                        (data->pMessage != nullptr ? data->pMessage : ""));
  } catch (...) {
  }
  return VK_FALSE;  // VK_TRUE would make the reported call fail; we only want to record
}

bool HasLayer(const vk::raii::Context& context, std::string_view name) {
  const auto layers = context.enumerateInstanceLayerProperties();
  return std::any_of(layers.begin(), layers.end(),
                     [&](const vk::LayerProperties& layer) { return std::string_view(layer.layerName) == name; });
}

bool HasExtension(const std::vector<vk::ExtensionProperties>& extensions, std::string_view name) {
  return std::any_of(extensions.begin(), extensions.end(),
                     [&](const vk::ExtensionProperties& e) { return std::string_view(e.extensionName) == name; });
}

// Throws GpuUnavailable unless the validation layer is installed with the extensions
// CreateInstance enables for it.
void CheckValidationLayer(const vk::raii::Context& context) {
  if (!HasLayer(context, kValidationLayer)) {
    throw GpuUnavailable(
        "the Vulkan validation layer VK_LAYER_KHRONOS_validation is not installed; install it "
        "with `apt-get install vulkan-validationlayers`");
  }
  const auto layer_extensions = context.enumerateInstanceExtensionProperties(std::string(kValidationLayer));
  const auto loader_extensions = context.enumerateInstanceExtensionProperties();
  for (const char* name : {VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, VK_EXT_DEBUG_UTILS_EXTENSION_NAME}) {
    if (!HasExtension(layer_extensions, name) && !HasExtension(loader_extensions, name)) {
      throw GpuUnavailable(std::string("the Vulkan validation layer lacks ") + name +
                           "; install a current one with `apt-get install vulkan-validationlayers`");
    }
  }
}

// Warnings and errors of every type, stored into `messages` by StoreMessage.
vk::DebugUtilsMessengerCreateInfoEXT MessengerInfo(std::vector<std::string>* messages) {
  vk::DebugUtilsMessengerCreateInfoEXT info{
      .messageSeverity =
          vk::DebugUtilsMessageSeverityFlagBitsEXT::eWarning | vk::DebugUtilsMessageSeverityFlagBitsEXT::eError,
      .messageType = vk::DebugUtilsMessageTypeFlagBitsEXT::eGeneral |
                     vk::DebugUtilsMessageTypeFlagBitsEXT::eValidation |
                     vk::DebugUtilsMessageTypeFlagBitsEXT::ePerformance,
      .pUserData = messages,
  };
  // Set through the C view of the struct: the C callback type takes the C enums in every
  // Vulkan-Hpp release, while 1.4 retyped the C++ member to take vk:: types.
  static_cast<VkDebugUtilsMessengerCreateInfoEXT&>(info).pfnUserCallback = &StoreMessage;
  return info;
}

// How well a usable device fits, higher is better: 0 (not to be chosen) when a name is asked that
// does not ask for it (base/device_names.hpp); else 3 for lavapipe, 2 for another CPU device, 1
// for any other, so that a name several devices answer to picks as the default would.
int DeviceScore(const vk::PhysicalDeviceProperties& properties, const std::string& wanted) {
  const std::string_view name = properties.deviceName.data();
  if (!wanted.empty() && !AsksForDevice(wanted, name)) return 0;
  const bool cpu = properties.deviceType == vk::PhysicalDeviceType::eCpu;
  return FamilyOfDevice(name) == &kLavapipeFamily ? 3 : cpu ? 2 : 1;
}

// The queue family we draw with, if the device can do everything the renderer needs: graphics
// and a D32_SFLOAT depth buffer.
std::optional<std::uint32_t> UsableQueueFamily(const vk::raii::PhysicalDevice& device) {
  const vk::FormatProperties depth = device.getFormatProperties(vk::Format::eD32Sfloat);
  if (!(depth.optimalTilingFeatures & vk::FormatFeatureFlagBits::eDepthStencilAttachment)) {
    return std::nullopt;
  }
  const auto families = device.getQueueFamilyProperties();
  for (std::uint32_t i = 0; i < families.size(); ++i) {
    // Graphics queues always support transfers too, which the readback copy needs.
    if (families[i].queueFlags & vk::QueueFlagBits::eGraphics) return i;
  }
  return std::nullopt;
}

// Each device by the names it can be asked by: "lavapipe (llvmpipe (LLVM 15.0.6, 256 bits)), ...".
std::string DeviceNames(const std::vector<vk::raii::PhysicalDevice>& devices) {
  std::string names;
  for (const auto& device : devices) {
    if (!names.empty()) names += ", ";
    names += AskableName(device.getProperties().deviceName.data());
  }
  return names.empty() ? "none" : names;
}

// No device answers to `wanted`: which do, and what a backend's name means.
std::string NoDeviceNamed(const std::string& wanted, const std::vector<vk::raii::PhysicalDevice>& devices) {
  std::string text = "--device '" + wanted +
                     "' matches none (a device answers to its common name or to any part of its full name, in "
                     "any case); the devices here: " +
                     DeviceNames(devices);
  if (const std::string hint = BackendNotDevice(wanted); !hint.empty()) text += "; " + hint;
  return text;
}

}  // namespace

// The loader is linked in (Vulkan::Vulkan), so we hand vulkan.hpp its entry point directly rather
// than have it dlopen the library a second time.
VulkanContext::VulkanContext(const GpuOptions& options) : context_(&vkGetInstanceProcAddr) {
  // lavapipe, whenever the name may ask for it, comes first with its driver alone (loading
  // SwiftShader's costs instance creation time); it is also the one chosen when every driver is
  // loaded. Any other name may ask for a device outside the loader's search path.
  if (!MayAskForFamily(options.device, kLavapipeFamily) || !ChooseLavapipeAlone(options.validation, options.device)) {
    const ExtraDriverOffer offer(!options.device.empty());
    CreateInstance(options.validation);
    ChooseDevice(options.device);
  }
  CreateDevice();
  KeepVulkanLibrariesLoaded();  // sanitizer builds only: see keep_loaded.hpp
}

// The device `wanted` asks for (any, when empty) from an instance with lavapipe's driver alone;
// false (and no instance) when the user's variables choose the drivers, or lavapipe is missing,
// unusable or not asked for.
bool VulkanContext::ChooseLavapipeAlone(bool validation, const std::string& wanted) {
  const LavapipeAlone alone;
  if (alone.manifest().empty()) return false;
  try {
    CreateInstance(validation);
    ChooseDevice(wanted);
    return true;
  } catch (const GpuUnavailable&) {
    messenger_ = nullptr;  // before its instance
    instance_ = nullptr;
    messages_.clear();  // the loader's complaint that it found no driver: the fallback decides
    return false;
  }
}

void VulkanContext::CreateInstance(bool validation) {
  std::vector<const char*> layers;
  std::vector<const char*> extensions;
  if (validation) {
    CheckValidationLayer(context_);
    extensions = {VK_EXT_VALIDATION_FEATURES_EXTENSION_NAME, VK_EXT_DEBUG_UTILS_EXTENSION_NAME};
    layers.push_back(kValidationLayer);
  }
  const std::vector<vk::ValidationFeatureEnableEXT> enabled_features = {
      vk::ValidationFeatureEnableEXT::eSynchronizationValidation};
  const vk::DebugUtilsMessengerCreateInfoEXT messenger_info = MessengerInfo(&messages_);
  // Chained into vkCreateInstance: the layer reads its feature list there, and a messenger in the
  // chain also hears about vkCreateInstance / vkDestroyInstance themselves.
  const vk::ValidationFeaturesEXT validation_features{
      .pNext = &messenger_info,
      .enabledValidationFeatureCount = static_cast<std::uint32_t>(enabled_features.size()),
      .pEnabledValidationFeatures = enabled_features.data(),
  };
  const vk::ApplicationInfo app_info{
      .pApplicationName = "twinraster",
      .applicationVersion = 1,
      .pEngineName = "twinraster",
      .engineVersion = 1,
      // Drawing needs only core Vulkan 1.0; 1.1 makes vkGetPhysicalDeviceProperties2 core, which
      // reads the driver's name and version (DeviceIdentity).
      .apiVersion = VK_API_VERSION_1_1,
  };
  const vk::InstanceCreateInfo instance_info{
      .pNext = validation ? &validation_features : nullptr,
      .pApplicationInfo = &app_info,
      .enabledLayerCount = static_cast<std::uint32_t>(layers.size()),
      .ppEnabledLayerNames = layers.data(),
      .enabledExtensionCount = static_cast<std::uint32_t>(extensions.size()),
      .ppEnabledExtensionNames = extensions.data(),
  };
  try {
    instance_ = vk::raii::Instance(context_, instance_info);
  } catch (const vk::SystemError& error) {
    throw GpuUnavailable(std::string("cannot create a Vulkan instance (") + error.what() +
                         "); install a Vulkan driver, e.g. `apt-get install mesa-vulkan-drivers` "
                         "for lavapipe");
  }
  if (validation) messenger_ = vk::raii::DebugUtilsMessengerEXT(instance_, messenger_info);
}

// Of the usable devices that `wanted` asks for (all of them when it is empty): lavapipe, else
// another CPU device (the same pixels on every machine; SwiftShader is one), else the first.
void VulkanContext::ChooseDevice(const std::string& wanted) {
  const std::vector<vk::raii::PhysicalDevice> devices = instance_.enumeratePhysicalDevices();
  const vk::raii::PhysicalDevice* chosen = nullptr;
  std::uint32_t chosen_family = 0;
  int chosen_score = 0;
  for (const vk::raii::PhysicalDevice& device : devices) {
    const std::optional<std::uint32_t> family = UsableQueueFamily(device);
    if (!family) continue;
    const int score = DeviceScore(device.getProperties(), wanted);
    if (score > chosen_score) {
      chosen = &device;
      chosen_family = *family;
      chosen_score = score;
    }
  }
  if (chosen == nullptr) {
    if (!wanted.empty()) throw GpuUnavailable(NoDeviceNamed(wanted, devices));
    throw GpuUnavailable(
        "no Vulkan device supports what the renderer needs (a graphics queue and "
        "D32_SFLOAT depth); devices present: " +
        DeviceNames(devices) + "; install lavapipe with `apt-get install mesa-vulkan-drivers`");
  }
  physical_device_ = *chosen;
  queue_family_ = chosen_family;
  properties_ = physical_device_.getProperties();
  memory_properties_ = physical_device_.getMemoryProperties();
  identity_ = Identify(physical_device_, properties_);
}

void VulkanContext::CreateDevice() {
  const float priority = 1.0f;
  const vk::DeviceQueueCreateInfo queue_info{
      .queueFamilyIndex = queue_family_,
      .queueCount = 1,
      .pQueuePriorities = &priority,
  };
  // One optional feature, for wireframe drawing (polygonMode LINE), when the device has it.
  const vk::PhysicalDeviceFeatures features{.fillModeNonSolid = physical_device_.getFeatures().fillModeNonSolid};
  wireframe_ = features.fillModeNonSolid == VK_TRUE;
  device_ = vk::raii::Device(physical_device_, vk::DeviceCreateInfo{
                                                   .queueCreateInfoCount = 1,
                                                   .pQueueCreateInfos = &queue_info,
                                                   .pEnabledFeatures = &features,
                                               });
  queue_ = device_.getQueue(queue_family_, 0);
}

std::uint32_t VulkanContext::FindMemoryType(std::uint32_t type_bits, vk::MemoryPropertyFlags required,
                                            vk::MemoryPropertyFlags preferred) const {
  std::optional<std::uint32_t> fallback;
  for (std::uint32_t i = 0; i < memory_properties_.memoryTypeCount; ++i) {
    const vk::MemoryPropertyFlags flags = memory_properties_.memoryTypes[i].propertyFlags;
    if ((type_bits & (1u << i)) == 0 || (flags & required) != required) continue;
    if ((flags & preferred) == preferred) return i;
    if (!fallback) fallback = i;
  }
  if (!fallback) throw std::runtime_error("no Vulkan memory type with " + vk::to_string(required));
  return *fallback;
}

}  // namespace twinraster::gpu
