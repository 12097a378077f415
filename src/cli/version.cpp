#include "cli/version.hpp"

#include "cli/build_version.hpp"  // generated at build time by build_version.cmake
#include "cpu/lavapipe_path.hpp"
#include "cpu/twin_rules.hpp"

namespace twinraster {

std::string VersionText() {
  const std::string describe = TWINRASTER_GIT_DESCRIBE;
  // No Vulkan here (--version stays instant): the driver is named by render's report.
  return std::string("twinraster ") + TWINRASTER_VERSION + (describe.empty() ? "" : " (" + describe + ")") +
         "\nlavapipe's CPU path on this machine: " + cpu::DetectCpuPath().Text() +
         "\nthe twin has bit-exact rules for:\n" + cpu::KnownRulesText() +
         "any other driver is reported as \"no bit-exact rules for ...\" (render names the driver)";
}

}  // namespace twinraster
