#include "cli/version.hpp"

#include "base/device_names.hpp"
#include "cli/build_version.hpp"  // generated at build time by build_version.cmake
#include "gpu/device_list.hpp"
#include "gpu/driver_files.hpp"
#include "run/backend_draws.hpp"
#include "twin_rules/lavapipe_path.hpp"
#include "twin_rules/twin_rules.hpp"

namespace twinraster::cli {
namespace {

// "lavapipe (llvmpipe (...)): llvmpipe, Mesa 22.3.6 (LLVM 15.0.6), Vulkan 1.3.230, 8 subpixel bits,
// strictLines true; twin: bit-exact (lavapipe rules, ...)": the device by the names --device takes.
std::string DeviceLine(const gpu::DeviceIdentity& d, const twin_rules::CpuPath& path) {
  std::string driver = d.driver_name;
  if (!d.driver_info.empty()) driver += (driver.empty() ? "" : ", ") + d.driver_info;
  const twin_rules::TwinRules twin = twin_rules::ChooseTwinRules(run::FactsOf(d), path);
  return "  " + AskableName(d.name) + ": " + (driver.empty() ? "driver not named" : driver) + ", Vulkan " +
         gpu::VulkanVersionText(d.api_version) + ", " + std::to_string(d.subpixel_bits) +
         " subpixel bits, strictLines " + (d.strict_lines ? "true" : "false") + "; twin: " +
         (twin.exact ? "bit-exact (" + twin.text + ")" : "no bit-exact rules (the verifier judges its images)");
}

std::string DevicesText(const twin_rules::CpuPath& path) {
  const gpu::ExtraDriverOffer offer;  // held across ListDevices(), whose own offer then stands aside
  std::string heading = "Vulkan devices, by the names --device takes", offered;
  for (const std::string& file : offer.files()) offered += (offered.empty() ? "" : ", ") + file;
  if (!offered.empty()) heading += " (also offered to the loader: " + offered + ")";
  try {
    const std::vector<gpu::DeviceIdentity> devices = gpu::ListDevices();
    if (devices.empty()) return heading + ": none reachable (the loader found no device)";
    std::string text = heading + ":";
    for (const gpu::DeviceIdentity& device : devices) text += "\n" + DeviceLine(device, path);
    return text;
  } catch (const gpu::GpuUnavailable& e) {
    return heading + ": none reachable (" + e.what() + ")";
  }
}

}  // namespace

std::string VersionText() {
  const std::string describe = TWINRASTER_GIT_DESCRIBE;
  const twin_rules::CpuPath path = twin_rules::DetectCpuPath();
  return std::string("twinraster ") + TWINRASTER_VERSION + (describe.empty() ? "" : " (" + describe + ")") +
         "\nlavapipe's CPU path on this machine: " + path.Text() + "\nthe twin has bit-exact rules for:\n" +
         twin_rules::KnownRulesText() +
         "any other driver is reported as \"no bit-exact rules for ...\" (render names the driver)\n" +
         DevicesText(path);
}

}  // namespace twinraster::cli
