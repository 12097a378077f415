// Which driver files the Vulkan loader reads: Debian's drivers outside its search path (Chromium's
// SwiftShader) offered when a device is asked by name, so `--device swiftshader` works without
// VK_ICD_FILENAMES; lavapipe's alone for the default device, so that no other driver is loaded.
// It loads no driver, picks no device, and never overrides a loader variable the user set.
#pragma once

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster::gpu {

// ICD manifests outside /usr/share/vulkan/icd.d. Debian's chromium-common (a dependency of
// chromium) installs SwiftShader's here, libvk_swiftshader.so beside it.
inline constexpr std::array<std::string_view, 1> kExtraDriverFiles = {
    "/usr/lib/chromium/vk_swiftshader_icd.json",
};

// For its lifetime, when none of VK_ICD_FILENAMES, VK_DRIVER_FILES, VK_ADD_DRIVER_FILES is in the
// environment (even empty: the loader then finds no driver at all, and that is the user's call),
// sets VK_ADD_DRIVER_FILES to the kExtraDriverFiles that exist; unsets it again when destroyed.
// Scoped, not process-wide: a later default renderer must not load SwiftShader (nor pick it: it
// is a CPU device too). The loader reads the variable when an instance is created, so hold the
// offer across vkCreateInstance, and create no instance on another thread meanwhile.
class ExtraDriverOffer {
 public:
  explicit ExtraDriverOffer(bool wanted = true);
  ~ExtraDriverOffer();
  ExtraDriverOffer(const ExtraDriverOffer&) = delete;
  ExtraDriverOffer& operator=(const ExtraDriverOffer&) = delete;

  // The files offered; empty when not wanted, when the user's variables are set, when an outer
  // offer is active, or when none is installed.
  const std::vector<std::string>& files() const { return files_; }

 private:
  std::vector<std::string> files_;
};

// For its lifetime, when no loader variable that chooses drivers is in the environment and
// lavapipe's manifest is installed (lvp_icd.<arch>.json, or lvp_icd.json from Mesa 25), sets
// VK_DRIVER_FILES to that manifest alone, and unsets it again when destroyed. The loader loads every driver it finds
// when an instance is created; each Mesa driver maps and relocates a large library (tens of milliseconds for all of
// Debian's), and the default device is lavapipe whenever it is installed. (VK_LOADER_DRIVERS_SELECT would filter too,
// but the loader then warns through the validation messenger about every driver it leaves out.) The caller falls back
// to every driver when this finds no usable device.
class LavapipeAlone {
 public:
  LavapipeAlone();
  ~LavapipeAlone();
  LavapipeAlone(const LavapipeAlone&) = delete;
  LavapipeAlone& operator=(const LavapipeAlone&) = delete;

  // The manifest offered; empty when the user's variables decide, or none is installed.
  const std::string& manifest() const { return manifest_; }

 private:
  std::string manifest_;
};

}  // namespace twinraster::gpu
