// The browser module's bytes, embedded in the native build (twinraster_page_module_blob): what
// explain --html writes into its page, base64, so that the page needs no second file. The .cpp is
// generated at build time from the module the build compiled (cmake/BrowserModule.cmake); it does
// not compile or check the module, and a build without the wasm32-wasi toolchain has no bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace twinraster::page_module {

// The module (twinraster_page.wasm); empty when this build has none.
std::span<const std::uint8_t> ModuleBytes();

// One line saying why this build has no module, naming the packages it needs; "" when it has one.
std::string_view ModuleMissingReason();

}  // namespace twinraster::page_module
