// Integer floor and ceiling of a quotient, exact for either sign of the dividend: what the
// rasterizers' span ends are made of. It does not guard against a zero or negative divisor.
#pragma once

#include <cstdint>

namespace twinraster::cpu {

// floor(a / b) for b > 0 (C++'s / truncates toward zero).
inline std::int64_t FloorDiv(std::int64_t a, std::int64_t b) {
  const std::int64_t q = a / b;
  return (a % b != 0 && a < 0) ? q - 1 : q;
}

// ceil(a / b) for b > 0.
inline std::int64_t CeilDiv(std::int64_t a, std::int64_t b) { return -FloorDiv(-a, b); }

}  // namespace twinraster::cpu
