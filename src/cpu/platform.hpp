// Everything the twin asks of the processor, in one place: the float control word (MXCSR's
// denormals as zero), the float-to-int conversions both devices' JIT code uses, the spin-loop
// pause, the CPUID features lavapipe's path is chosen from, and which rules this platform can
// follow. x86-64 code lives here only; every other platform takes the portable branch, which gives
// the same results where it can and says where it cannot (CanFollow). It chooses no rules
// (twin_rules/twin_rules.hpp does) and renders nothing.
#pragma once

#include "cpu/raster_rules.hpp"

#if defined(__SSE__) || defined(__x86_64__)
#define TWINRASTER_X86_SSE 1
#include <xmmintrin.h>
#if defined(__SSE2__) || defined(__x86_64__)
#include <emmintrin.h>
#endif
#endif

#include <cmath>
#include <cstdint>
#include <limits>

// On x86-64 GCC builds a second copy of a function for CPUs with FMA, chosen at load time, where
// fmaf is one instruction; the portable copy's fmaf is a library call, just as exact, only slower.
#if defined(__GNUC__) && defined(__x86_64__) && !defined(__clang__)
#define TWINRASTER_FMA_CLONES __attribute__((target_clones("fma", "default")))
#else
#define TWINRASTER_FMA_CLONES
#endif

namespace twinraster::cpu {

// Whether this build can set MXCSR's DAZ and FTZ: only x86 with SSE has them.
#ifdef TWINRASTER_X86_SSE
inline constexpr bool kHasDenormalsControl = true;
#else
inline constexpr bool kHasDenormalsControl = false;
#endif

// Whether the twin can follow `rules` bit for bit on this platform: denormals as zero need MXCSR
// (the conversions and the pause have portable forms that give the same results).
constexpr bool CanFollow(const RasterRules& rules) { return kHasDenormalsControl || !rules.flush_denormals; }

// Denormals as zero for one thread's stretch of work: MXCSR's DAZ (denormal inputs read as 0) and
// FTZ (denormal results become 0), as SwiftShader sets them in every worker thread that runs its
// shaders, clipping and set-up. It does not change rounding; where CanFollow says there is no such
// control it does nothing (no rules that ask for it are chosen there).
class DenormalsAsZero {
 public:
  explicit DenormalsAsZero(bool on) : on_(on) {
#ifdef TWINRASTER_X86_SSE
    if (!on_) return;
    saved_ = _mm_getcsr();
    _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
#endif
  }
  ~DenormalsAsZero() {
#ifdef TWINRASTER_X86_SSE
    if (on_) _mm_setcsr(saved_);
#endif
  }
  DenormalsAsZero(const DenormalsAsZero&) = delete;
  DenormalsAsZero& operator=(const DenormalsAsZero&) = delete;

 private:
  static constexpr unsigned kFlushToZero = 0x8000, kDenormalsAreZero = 0x0040;
  [[maybe_unused]] bool on_;
  [[maybe_unused]] unsigned saved_ = 0;
};

// The float control word as the calling thread has it (MXCSR on x86; 0 where there is none), so
// that a test can see the twin leaves it as it found it.
inline unsigned FloatControlWord() {
#ifdef TWINRASTER_X86_SSE
  return _mm_getcsr();
#else
  return 0;
#endif
}

// Float to int32 as x86-64's cvtss2si / cvtps2dq do it, the conversion both lavapipe's and
// SwiftShader's JIT code snap vertices with: round half to even under the default MXCSR, and the
// "integer indefinite" INT32_MIN for NaN and anything that does not fit. It does not saturate.
inline std::int32_t RoundHalfEvenToInt(float f) {
#ifdef TWINRASTER_X86_SSE
  return _mm_cvtss_si32(_mm_set_ss(f));
#else
  if (!(f >= -2147483648.0f && f < 2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(std::lrintf(f));  // default rounding: half to even
#endif
}

// C's (int)f as x86-64 compiles it (cvttss2si): toward zero; NaN and out of range give INT32_MIN
// (where plain C++ would be undefined).
inline std::int32_t TruncateToInt(float f) {
#ifdef TWINRASTER_X86_SSE
  return _mm_cvtt_ss2si(_mm_set_ss(f));
#else
  if (!(f > -2147483649.0f && f < 2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(f);
#endif
}

// Pause inside a spin loop (lets the other hyper-thread run and saves power); nothing elsewhere.
inline void CpuRelax() {
#if defined(__x86_64__) || defined(__SSE2__)
  _mm_pause();
#endif
}

// The processor's features as CPUID reports them, a feature counting only when the OS saves its
// registers (XCR0), as Mesa's _util_cpu_detect_once reads them. On another architecture: its name
// and every feature false.
struct CpuFeatures {
  const char* arch = "other";  // "x86-64", "aarch64" or "other"
  bool sse = false, sse2 = false, sse3 = false, ssse3 = false, sse4_1 = false, avx = false, avx2 = false, fma = false,
       avx512f = false;
};
CpuFeatures ReadCpuFeatures();

}  // namespace twinraster::cpu
