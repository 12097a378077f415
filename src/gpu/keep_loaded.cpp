#include "gpu/keep_loaded.hpp"

#if defined(__has_feature)
#if __has_feature(address_sanitizer)
#define TWINRASTER_ASAN 1
#endif
#endif
#if defined(__SANITIZE_ADDRESS__)
#define TWINRASTER_ASAN 1
#endif

#ifdef TWINRASTER_ASAN
#include <dlfcn.h>
#include <link.h>

#include <string_view>
#endif

namespace twinraster::gpu {

void KeepVulkanLibrariesLoaded() {
#ifdef TWINRASTER_ASAN
  // Every loaded Vulkan driver (Mesa's libvulkan_*.so, SwiftShader's libvk_swiftshader.so) and
  // layer (libVkLayer_*.so): opened once more with RTLD_NODELETE, which keeps an already loaded
  // object mapped until exit.
  dl_iterate_phdr(
      [](dl_phdr_info* info, std::size_t, void*) {
        const std::string_view name = info->dlpi_name != nullptr ? info->dlpi_name : "";
        if (name.find("libvulkan_") != std::string_view::npos || name.find("libvk_") != std::string_view::npos ||
            name.find("libVkLayer_") != std::string_view::npos) {
          dlopen(info->dlpi_name, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
        }
        return 0;
      },
      nullptr);
#endif
}

}  // namespace twinraster::gpu
