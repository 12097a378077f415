// The proof that std::fmaf is exact where the module runs (docs/building.md#the-browser-module):
// fmaf on random and constructed float triples, each result's bits compared with a reference
// computed exactly in integers. The twin's fused rows (the viewport transform, the depth plane)
// need one rounding of a * b + c; WebAssembly has no fused instruction, so the module's fmaf is
// wasi-libc's (musl's) software one. It tests only fmaf, and proves nothing about other functions.
#pragma once

#include <cstdint>

namespace twinraster::page_module {

struct FmafCheck {
  std::uint32_t cases = 0;         // triples tried
  std::uint32_t mismatches = 0;    // results whose bits differ from the exact reference
  std::uint64_t digest = 0;        // FNV-1a over every result's bits, in order: equal across builds
  float first_bad[3] = {0, 0, 0};  // the first mismatching triple (a, b, c), if any
};

// a * b + c rounded once, to nearest with ties to even, as IEEE 754 defines fusedMultiplyAdd, in
// integer arithmetic only. Any NaN result is the default quiet NaN.
float ExactFmaf(float a, float b, float c);

// std::fmaf against ExactFmaf on `random_cases` triples drawn from `seed` (the ranges the twin's
// fused rows see, any bit pattern, and near cancellation) and on the constructed hard cases:
// products that are float midpoints nudged by a tiny c (where rounding first to double and then
// to float goes wrong), signed zeros, overflow, underflow and subnormal results.
FmafCheck CheckFmaf(std::uint32_t seed, std::uint32_t random_cases);

}  // namespace twinraster::page_module
