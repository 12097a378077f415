// The reference the project's own sine, cosine, tangent and sRGB bytes are measured against:
// quadruple precision (__float128, 113 bits, and GCC's libquadmath), where the platform has it
// (TWINRASTER_QUAD_REFERENCE, set by tests/base/CMakeLists.txt). It measures; it does not say
// what a test expects.
#pragma once

#ifdef TWINRASTER_QUAD_REFERENCE

#include <cmath>
#include <cstdint>

namespace twinraster::test {

using Quad = __float128;

// libquadmath's functions, declared here: clang does not see GCC's <quadmath.h>.
extern "C" {
Quad sinq(Quad);
Quad cosq(Quad);
Quad tanq(Quad);
Quad powq(Quad, Quad);
Quad atanq(Quad);
Quad sqrtq(Quad);
}

inline Quad QuadPi() { return 4 * atanq(1); }

// |value - truth| in units in the last place of the double nearest the truth, in truth's binade.
inline double UlpError(double value, Quad truth) {
  const double nearest = static_cast<double>(truth);
  const Quad size = truth < 0 ? -truth : truth;
  int exponent = 0;
  std::frexp(nearest, &exponent);  // |nearest| = m · 2^exponent, 0.5 ≤ m < 1
  if (std::fabs(nearest) == std::ldexp(0.5, exponent) && size < static_cast<Quad>(std::fabs(nearest))) --exponent;
  const double ulp = std::ldexp(1.0, std::max(exponent - 53, -1074));
  const Quad error = static_cast<Quad>(value) - truth;
  return static_cast<double>((error < 0 ? -error : error) / static_cast<Quad>(ulp));
}

// Whether value is the double nearest the truth (the conversion rounds to nearest, ties to even).
inline bool CorrectlyRounded(double value, Quad truth) { return value == static_cast<double>(truth); }

}  // namespace twinraster::test

#endif
