// Float to int32 as x86-64's cvtss2si / cvtps2dq do it, the conversion both lavapipe's and
// SwiftShader's JIT code snap vertices with: round half to even under the default MXCSR, and the
// "integer indefinite" INT32_MIN for NaN and anything that does not fit. It does not saturate.
#pragma once

#if defined(__SSE__) || defined(__x86_64__)
#include <xmmintrin.h>
#endif

#include <cmath>
#include <cstdint>
#include <limits>

namespace twinraster::cpu {

inline std::int32_t RoundHalfEvenToInt(float f) {
#if defined(__SSE__) || defined(__x86_64__)
  return _mm_cvtss_si32(_mm_set_ss(f));
#else
  if (!(f >= -2147483648.0f && f < 2147483648.0f)) return std::numeric_limits<std::int32_t>::min();
  return static_cast<std::int32_t>(std::lrintf(f));  // default rounding: half to even
#endif
}

}  // namespace twinraster::cpu
