// The exit codes every command shares, in one place: the commands return them and render's JSON
// reports each scene's. Which verdict gives which is run/verdict.hpp's ExitCodeOf.
#pragma once

namespace twinraster {

enum ExitCode : int {
  kExitOk = 0,
  kExitImagesDiffer = 1,
  kExitBadInput = 2,
  kExitNoVulkan = 3,
  kExitInternalError = 4,
  kExitGpuFailed = 5,     // the Vulkan driver crashed or timed out; everything else was still done
  kExitInconclusive = 6,  // no pixel is wrong, but the verifier could not tell a correct image from a broken one
};

}  // namespace twinraster
