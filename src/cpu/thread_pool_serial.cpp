// thread_pool.hpp for a build without threads (the browser module: wasm32-wasi has none): every
// part runs on the calling thread, in order. The results are the same, since each part writes only
// its own outputs; src/cpu/CMakeLists.txt chooses this file or thread_pool.cpp.
#include "cpu/thread_pool.hpp"

namespace twinraster::cpu {

unsigned HardwareThreads() { return 1; }

void RunParts(unsigned parts, const std::function<void(unsigned)>& fn) {
  for (unsigned part = 0; part < parts; ++part) fn(part);
}

KeepPoolSpinning::KeepPoolSpinning() = default;
KeepPoolSpinning::~KeepPoolSpinning() = default;

}  // namespace twinraster::cpu
