#include "cli/version.hpp"

#include "cli/build_version.hpp"  // generated at build time by build_version.cmake

namespace twinraster {

std::string VersionText() {
  const std::string describe = TWINRASTER_GIT_DESCRIBE;
  return std::string("twinraster ") + TWINRASTER_VERSION + (describe.empty() ? "" : " (" + describe + ")");
}

}  // namespace twinraster
