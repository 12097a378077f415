#include "cpu/platform.hpp"

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace twinraster::cpu {

#if defined(__x86_64__)
namespace {

std::uint64_t ReadXcr0() {
  std::uint32_t eax = 0, edx = 0;
  __asm__ volatile("xgetbv" : "=a"(eax), "=d"(edx) : "c"(0));
  return (std::uint64_t{edx} << 32) | eax;
}

}  // namespace

CpuFeatures ReadCpuFeatures() {
  CpuFeatures cpu;
  cpu.arch = "x86-64";
  unsigned a = 0, b = 0, c = 0, d = 0;
  if (__get_cpuid(1, &a, &b, &c, &d) == 0) return cpu;
  const bool osxsave = (c >> 27) & 1;
  const std::uint64_t xcr0 = osxsave ? ReadXcr0() : 0;
  cpu.sse = (d >> 25) & 1;
  cpu.sse2 = (d >> 26) & 1;
  cpu.sse3 = c & 1;
  cpu.ssse3 = (c >> 9) & 1;
  cpu.sse4_1 = (c >> 19) & 1;
  cpu.avx = ((c >> 28) & 1) && osxsave && (xcr0 & 6) == 6;
  cpu.fma = ((c >> 12) & 1) && cpu.avx;
  if (cpu.avx && __get_cpuid_count(7, 0, &a, &b, &c, &d) != 0) {
    cpu.avx2 = (b >> 5) & 1;
    if (xcr0 & (0x7 << 5)) cpu.avx512f = (b >> 16) & 1;
  }
  return cpu;
}
#else
CpuFeatures ReadCpuFeatures() {
  CpuFeatures cpu;
#if defined(__aarch64__)
  cpu.arch = "aarch64";
#endif
  return cpu;
}
#endif

}  // namespace twinraster::cpu
