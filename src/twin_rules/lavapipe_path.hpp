// The CPU path lavapipe's JIT takes on this machine, found as Mesa finds it: CPUID (with the OS's
// consent to AVX state), then GALLIUM_OVERRIDE_CPU_CAPS, then LP_NATIVE_VECTOR_WIDTH
// (docs/lavapipe-paths.md gives Mesa's file and line for each step).
#pragma once

#include <string>

namespace twinraster::twin_rules {

struct CpuPath {
  std::string arch;  // "x86-64", "aarch64", or what the build targets otherwise
  // Mesa's util_cpu_caps after GALLIUM_OVERRIDE_CPU_CAPS (x86-64 only; all false elsewhere).
  bool sse = false, sse2 = false, sse3 = false, ssse3 = false, sse4_1 = false, avx = false, avx2 = false, fma = false,
       avx512f = false;
  // SSE4.1 as CPUID reports it, before Mesa's overrides: SwiftShader's JIT reads CPUID alone.
  bool cpuid_sse4_1 = false;
  std::string override_caps;  // GALLIUM_OVERRIDE_CPU_CAPS as set, empty when unset
  int vector_bits = 0;        // llvmpipe's native vector width, LP_NATIVE_VECTOR_WIDTH included
  bool vector_bits_overridden = false;

  // The instruction set that decides the arithmetic: "AVX2+FMA", "AVX", "SSE4.1", "SSSE3",
  // ..., "no SSE" on x86-64; "NEON" on aarch64.
  std::string InstructionSet() const;
  // "x86-64 AVX2+FMA, 256-bit", with the variables that chose it when set.
  std::string Text() const;
};

// Reads this CPU and this process's environment.
CpuPath DetectCpuPath();

// The same decision from given CPUID feature bits and variable values, for tests. `cpu` starts as
// CPUID reports (before overrides); `override_caps` and `vector_width` as the variables read (empty
// for unset).
CpuPath ApplyMesaOverrides(CpuPath cpu, const std::string& override_caps, const std::string& vector_width);

}  // namespace twinraster::twin_rules
