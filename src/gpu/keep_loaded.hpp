// Under LeakSanitizer only: keeps the Vulkan driver and layers mapped until the process exits.
#pragma once

namespace twinraster::gpu {

// The loader unloads lavapipe and the validation layer when the last instance goes; what they
// keep for the life of the process (reachable only from their own globals) then looks leaked, in
// frames LeakSanitizer can no longer name. Pinning them (RTLD_NODELETE) keeps those globals in
// view, so that only real leaks are reported. Does nothing in builds without AddressSanitizer.
void KeepVulkanLibrariesLoaded();

}  // namespace twinraster::gpu
