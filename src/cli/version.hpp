// What `twinraster --version` prints: the project version and, when built from a git checkout,
// which commit (git describe --always, "-dirty" when tracked files had changes); then the CPU path
// lavapipe takes on this machine and the lavapipe releases and paths the twin copies bit for bit;
// then every Vulkan device this process reaches and whether the twin copies it bit for bit.
#pragma once

#include <string>

namespace twinraster::cli {

// "twinraster 0.1.0 (93a62fb-dirty)\n..." Creates a Vulkan instance (with Chromium's SwiftShader
// offered, gpu/driver_files.hpp), so call it only when --version is given. Never throws for a
// missing Vulkan: the device list then says why none is reachable.
std::string VersionText();

}  // namespace twinraster::cli
