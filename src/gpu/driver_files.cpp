#include "gpu/driver_files.hpp"

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <string_view>

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

// The names Mesa gives lavapipe's manifest: per architecture (Mesa 22.3, Debian 12: its
// meson.build names the host CPU family, as uname -m says it), or one name for all (Mesa 25.0,
// Debian 13, whose manifest names the library without a directory).
constexpr std::string_view kLavapipeManifests[] = {
#if defined(__x86_64__)
    "lvp_icd.x86_64.json",
#elif defined(__aarch64__)
    "lvp_icd.aarch64.json",
#endif
    "lvp_icd.json",
};

// The loader's system search path for drivers (its docs, "Linux Driver Discovery"): /etc, then
// each XDG data directory, under vulkan/icd.d.
std::vector<std::filesystem::path> DriverDirectories() {
  std::vector<std::filesystem::path> directories = {"/etc/vulkan/icd.d"};
  const char* xdg = std::getenv("XDG_DATA_DIRS");
  const std::string data = xdg && *xdg ? xdg : "/usr/local/share:/usr/share";
  for (std::size_t begin = 0; begin <= data.size();) {
    const std::size_t end = std::min(data.find(':', begin), data.size());
    if (end > begin) directories.push_back(std::filesystem::path(data.substr(begin, end - begin)) / "vulkan/icd.d");
    begin = end + 1;
  }
  return directories;
}

std::string InstalledLavapipeManifest() {
  std::error_code error;  // unreadable counts as absent
  for (const std::filesystem::path& directory : DriverDirectories()) {
    for (const std::string_view name : kLavapipeManifests) {
      const std::filesystem::path file = directory / name;
      if (std::filesystem::exists(file, error)) return file.string();
    }
  }
  return "";
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
  manifest_ = InstalledLavapipeManifest();
  if (!manifest_.empty()) setenv("VK_DRIVER_FILES", manifest_.c_str(), 0);
}

LavapipeAlone::~LavapipeAlone() {
  if (!manifest_.empty()) unsetenv("VK_DRIVER_FILES");  // it was unset before: ours alone
}

}  // namespace twinraster::gpu
