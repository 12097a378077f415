// Denormals as zero for one thread's stretch of work: MXCSR's DAZ (denormal inputs read as 0) and
// FTZ (denormal results become 0), as SwiftShader sets them in every worker thread that runs its
// shaders, clipping and set-up. It does not change rounding; on a CPU without SSE it does nothing
// (no rules that ask for it are chosen there).
#pragma once

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

namespace twinraster::cpu {

class DenormalsAsZero {
 public:
  explicit DenormalsAsZero(bool on) : on_(on) {
#if defined(__SSE__) || defined(__x86_64__)
    if (!on_) return;
    saved_ = _mm_getcsr();
    _mm_setcsr(saved_ | kFlushToZero | kDenormalsAreZero);
#endif
  }
  ~DenormalsAsZero() {
#if defined(__SSE__) || defined(__x86_64__)
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

}  // namespace twinraster::cpu
