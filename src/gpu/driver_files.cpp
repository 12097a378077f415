#include "gpu/driver_files.hpp"

#include <cstdlib>
#include <filesystem>

namespace twinraster::gpu {
namespace {

bool LoaderVariablesSet() {
  for (const char* name : {"VK_ICD_FILENAMES", "VK_DRIVER_FILES", "VK_ADD_DRIVER_FILES"}) {
    if (std::getenv(name) != nullptr) return true;
  }
  return false;
}

// Those, and the loader's filters on the drivers it found.
bool DriverChoiceSet() {
  return LoaderVariablesSet() || std::getenv("VK_LOADER_DRIVERS_SELECT") != nullptr ||
         std::getenv("VK_LOADER_DRIVERS_DISABLE") != nullptr;
}

std::vector<std::string> InstalledExtraDrivers() {
  std::vector<std::string> files;
  std::error_code error;  // unreadable counts as absent
  for (const std::string_view file : kExtraDriverFiles) {
    if (std::filesystem::exists(file, error)) files.emplace_back(file);
  }
  return files;
}

}  // namespace

ExtraDriverOffer::ExtraDriverOffer(bool wanted) {
  if (!wanted || LoaderVariablesSet()) return;
  files_ = InstalledExtraDrivers();
  std::string joined;  // the loader's list separator on Linux is ':'
  for (const std::string& file : files_) joined += (joined.empty() ? "" : ":") + file;
  if (!joined.empty()) setenv("VK_ADD_DRIVER_FILES", joined.c_str(), 0);
}

ExtraDriverOffer::~ExtraDriverOffer() {
  if (!files_.empty()) unsetenv("VK_ADD_DRIVER_FILES");  // it was unset before: ours alone
}

LavapipeAlone::LavapipeAlone() {
  if (DriverChoiceSet()) return;
  // Matched against the manifest's file name: lvp_icd.x86_64.json, lvp_icd.aarch64.json, ...
  setenv("VK_LOADER_DRIVERS_SELECT", "*lvp_icd*", 0);
  active_ = true;
}

LavapipeAlone::~LavapipeAlone() {
  if (active_) unsetenv("VK_LOADER_DRIVERS_SELECT");  // it was unset before: ours alone
}

}  // namespace twinraster::gpu
