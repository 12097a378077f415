// Fork-join over the process's thread pool (thread_pool.hpp): fn(part) for each part, or
// fn(begin, end, part) over contiguous slices of [0, n). Each part writes only its own outputs,
// so results never depend on scheduling.
#pragma once

#include "cpu/thread_pool.hpp"

#include <algorithm>
#include <cstddef>

namespace twinraster::cpu {

// options.threads as the user gave it: 0 = one per hardware thread.
inline unsigned ResolveThreadCount(unsigned requested) {
  if (requested != 0) return requested;
  return std::max(1u, HardwareThreads());
}

template <class Fn>
void ParallelParts(unsigned parts, Fn&& fn) {
  RunParts(parts, [&fn](unsigned part) { fn(part); });
}

template <class Fn>
void ParallelFor(unsigned parts, std::size_t n, Fn&& fn) {
  parts = static_cast<unsigned>(std::max<std::size_t>(1, std::min<std::size_t>(parts, n)));
  ParallelParts(parts, [&](unsigned part) {
    const std::size_t begin = n * part / parts;
    const std::size_t end = n * (part + 1) / parts;
    fn(begin, end, part);
  });
}

}  // namespace twinraster::cpu
