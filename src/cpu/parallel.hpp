// A minimal fork-join helper: runs fn(begin, end, part) on `parts` threads over contiguous slices
// of [0, n), the calling thread taking part 0. Each part writes only its own outputs, so results
// never depend on scheduling.
#pragma once

#include <algorithm>
#include <cstddef>
#include <thread>
#include <vector>

namespace twinraster::cpu {

// options.threads as the user gave it: 0 = one per hardware thread.
inline unsigned ResolveThreadCount(unsigned requested) {
  if (requested != 0) return requested;
  return std::max(1u, std::thread::hardware_concurrency());
}

template <class Fn>
void ParallelParts(unsigned parts, Fn&& fn) {
  std::vector<std::thread> workers;
  workers.reserve(parts > 0 ? parts - 1 : 0);
  for (unsigned part = 1; part < parts; ++part) workers.emplace_back([&fn, part] { fn(part); });
  fn(0u);
  for (std::thread& t : workers) t.join();
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
