// What `twinraster --version` prints: the project version and, when built from a git checkout,
// which commit (git describe --always, "-dirty" when tracked files had changes); then the CPU path
// lavapipe takes on this machine and the lavapipe releases and paths the twin copies bit for bit.
#pragma once

#include <string>

namespace twinraster {

std::string VersionText();  // "twinraster 0.1.0 (93a62fb-dirty)", or "twinraster 0.1.0"

}  // namespace twinraster
