#include "cpu/lavapipe_path.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

#if defined(__x86_64__)
#include <cpuid.h>
#endif

namespace twinraster::cpu {
namespace {

std::string Environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

#if defined(__x86_64__)
std::uint64_t ReadXcr0() {
  std::uint32_t eax = 0, edx = 0;
  __asm__ volatile("xgetbv" : "=a"(eax), "=d"(edx) : "c"(0));
  return (std::uint64_t{edx} << 32) | eax;
}

// Mesa's _util_cpu_detect_once: a feature counts only when the OS saves its registers (XCR0).
CpuPath ReadCpuid() {
  CpuPath cpu;
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
  cpu.cpuid_sse4_1 = cpu.sse4_1;
  cpu.avx = ((c >> 28) & 1) && osxsave && (xcr0 & 6) == 6;
  cpu.fma = ((c >> 12) & 1) && cpu.avx;
  if (cpu.avx && __get_cpuid_count(7, 0, &a, &b, &c, &d) != 0) {
    cpu.avx2 = (b >> 5) & 1;
    if (xcr0 & (0x7 << 5)) cpu.avx512f = (b >> 16) & 1;
  }
  return cpu;
}
#else
CpuPath ReadCpuid() {
  CpuPath cpu;
#if defined(__aarch64__)
  cpu.arch = "aarch64";
#else
  cpu.arch = "other";
#endif
  return cpu;
}
#endif

}  // namespace

CpuPath ApplyMesaOverrides(CpuPath cpu, const std::string& override_caps, const std::string& vector_width) {
  cpu.override_caps = override_caps;
  if (cpu.arch == "x86-64") {
    // check_cpu_caps_override: each value clears one feature, and the features above it follow.
    if (override_caps == "nosse")
      cpu.sse = false;
    else if (override_caps == "sse")
      cpu.sse2 = false;
    else if (override_caps == "sse2")
      cpu.sse3 = false;
    else if (override_caps == "sse3")
      cpu.ssse3 = false;
    else if (override_caps == "ssse3")
      cpu.sse4_1 = false;
    else if (override_caps == "sse4.1")
      cpu.avx = false;
    else if (override_caps == "avx")
      cpu.avx512f = false;
    if (!cpu.sse) cpu.sse2 = false;
    if (!cpu.sse2) cpu.sse3 = false;
    if (!cpu.sse3) cpu.ssse3 = false;
    if (!cpu.ssse3) cpu.sse4_1 = false;
    if (!cpu.sse4_1) cpu.avx = false;
    if (!cpu.avx) cpu.avx2 = cpu.fma = cpu.avx512f = false;
  }
  // check_max_vector_bits, then lp_build_init's cap at LP_MAX_VECTOR_WIDTH (256) and the variable.
  cpu.vector_bits = cpu.avx ? 256 : 128;
  if (!vector_width.empty()) {
    char* end = nullptr;
    const long bits = std::strtol(vector_width.c_str(), &end, 10);
    if (end != vector_width.c_str()) {
      cpu.vector_bits = static_cast<int>(bits);
      cpu.vector_bits_overridden = true;
    }
  }
  return cpu;
}

CpuPath DetectCpuPath() {
  return ApplyMesaOverrides(ReadCpuid(), Environment("GALLIUM_OVERRIDE_CPU_CAPS"),
                            Environment("LP_NATIVE_VECTOR_WIDTH"));
}

std::string CpuPath::InstructionSet() const {
  if (arch == "aarch64") return "NEON";
  if (arch != "x86-64") return arch;
  if (!sse) return "no SSE";
  if (avx2 && fma) return "AVX2+FMA";
  if (avx && fma) return "AVX+FMA";
  if (avx) return "AVX";
  if (sse4_1) return "SSE4.1";
  if (ssse3) return "SSSE3";
  if (sse3) return "SSE3";
  if (sse2) return "SSE2";
  return "SSE";
}

std::string CpuPath::Text() const {
  std::string text = arch + " " + InstructionSet() + ", " + std::to_string(vector_bits) + "-bit";
  std::string chosen;
  if (!override_caps.empty()) chosen += "GALLIUM_OVERRIDE_CPU_CAPS=" + override_caps;
  if (vector_bits_overridden)
    chosen += std::string(chosen.empty() ? "" : ", ") + "LP_NATIVE_VECTOR_WIDTH=" + std::to_string(vector_bits);
  if (!chosen.empty()) text += " (" + chosen + ")";
  return text;
}

}  // namespace twinraster::cpu
