#include "twin_rules/lavapipe_path.hpp"

#include "cpu/platform.hpp"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace twinraster::twin_rules {
namespace {

std::string Environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

// The features CPUID reports (cpu/platform.hpp), before Mesa's overrides.
CpuPath ReadCpuid() {
  const cpu::CpuFeatures features = cpu::ReadCpuFeatures();
  CpuPath cpu;
  cpu.arch = features.arch;
  cpu.sse = features.sse;
  cpu.sse2 = features.sse2;
  cpu.sse3 = features.sse3;
  cpu.ssse3 = features.ssse3;
  cpu.sse4_1 = features.sse4_1;
  cpu.cpuid_sse4_1 = features.sse4_1;
  cpu.avx = features.avx;
  cpu.avx2 = features.avx2;
  cpu.fma = features.fma;
  cpu.avx512f = features.avx512f;
  return cpu;
}

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

}  // namespace twinraster::twin_rules
