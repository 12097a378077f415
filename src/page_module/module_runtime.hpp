// The browser module's message buffer, and the C++ runtime's pieces libc++abi for wasm32 lacks
// (module_runtime.cpp). It cannot unwind, so in the module a C++ throw ends the call: the
// exception's what() is copied into this buffer and the module traps, and the page reads the
// buffer and starts a fresh instance. A thread_local's destructor is never registered: the module
// has one thread, which never exits. And fmaf is the project's own, correctly rounded where
// wasi-libc's is not. Compiled into the browser build only; it catches nothing.
#pragma once

#include <cstdint>
#include <string_view>

namespace twinraster::page_module {

// The buffer's size: a longer message is cut at this many bytes.
inline constexpr std::uint32_t kMessageCapacity = 4096;

// The buffer, at a fixed address for the module's life (tr_message), and its text's length.
const char* MessageText();
std::uint32_t MessageSize();

// Replaces the message (cut to kMessageCapacity bytes).
void SetMessage(std::string_view text);

}  // namespace twinraster::page_module
