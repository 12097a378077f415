#include "page_module/fmaf_check.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>

namespace twinraster::page_module {

namespace {

// clang and GCC, wasm32 included (__extension__: not ISO C++): the exact sum of two float products.
__extension__ typedef __int128 Int128;
__extension__ typedef unsigned __int128 Uint128;

// A finite float as magnitude * 2^exponent, magnitude < 2^24.
struct Term {
  bool negative = false;
  Uint128 magnitude = 0;
  int exponent = 0;
};

Term Decompose(float f) {
  const std::uint32_t bits = std::bit_cast<std::uint32_t>(f);
  const std::uint32_t field = (bits >> 23) & 0xff, fraction = bits & 0x7fffff;
  Term t;
  t.negative = (bits >> 31) != 0;
  t.magnitude = field == 0 ? fraction : (fraction | 0x800000u);
  t.exponent = field == 0 ? -149 : static_cast<int>(field) - 150;
  return t;
}

int TopBit(Uint128 x) {
  int top = -1;
  for (; x != 0; x >>= 1) ++top;
  return top;
}

// x * 2^shift; for shift < 0, bits shifted out set the lowest bit (sticky). Bits are lost only from
// a term at least 76 bits below the other, whose aligned magnitude is a multiple of 2^78: the sum
// is then an odd integer next to the exact one, and every rounding boundary there is an even
// integer, so both round alike.
Uint128 ShiftSticky(Uint128 x, int shift) {
  if (shift >= 0) return x << shift;
  if (shift <= -128) return x != 0 ? 1 : 0;
  const Uint128 kept = x >> -shift;
  return kept | ((kept << -shift) != x ? 1 : 0);
}

// sign * magnitude * 2^exponent rounded to the nearest float, ties to even.
float RoundToFloat(bool negative, Uint128 magnitude, int exponent) {
  const std::uint32_t sign = negative ? 0x80000000u : 0;
  if (magnitude == 0) return std::bit_cast<float>(sign);
  const int top = TopBit(magnitude) + exponent;  // the value is in [2^top, 2^(top + 1))
  const int ulp = std::max(top - 23, -149);      // the exponent of the float's last bit there
  const int shift = ulp - exponent;
  Uint128 kept = 0;
  if (shift <= 0) {
    kept = magnitude << -shift;
  } else if (shift < 128) {
    kept = magnitude >> shift;
    const Uint128 rest = magnitude - (kept << shift), half = Uint128{1} << (shift - 1);
    if (rest > half || (rest == half && (kept & 1) != 0)) ++kept;
  }  // shift >= 128: the magnitude (< 2^127) is below half the smallest subnormal
  // Above the subnormals, kept is in [2^23, 2^24] and the encoding is (ulp + 149) * 2^23 + kept;
  // a carry to 2^24 lands on the next exponent by itself.
  const Uint128 bits = (Uint128(static_cast<unsigned>(ulp + 149)) << 23) + kept;
  if (bits >= 0x7f800000u) return std::bit_cast<float>(sign | 0x7f800000u);
  return std::bit_cast<float>(sign | static_cast<std::uint32_t>(bits));
}

float SpecialFmaf(float a, float b, float c) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  if (std::isnan(a) || std::isnan(b) || std::isnan(c)) return nan;
  if ((std::isinf(a) && b == 0) || (std::isinf(b) && a == 0)) return nan;
  if (std::isinf(a) || std::isinf(b)) {
    const bool negative = std::signbit(a) != std::signbit(b);
    if (std::isinf(c) && std::signbit(c) != negative) return nan;
    return negative ? -std::numeric_limits<float>::infinity() : std::numeric_limits<float>::infinity();
  }
  return c;  // c is infinite, the product finite
}

// splitmix64: a small, fixed generator, so that every build draws the same triples.
class Random {
 public:
  explicit Random(std::uint64_t seed) : state_(seed) {}
  std::uint64_t Next() {
    std::uint64_t z = (state_ += 0x9e3779b97f4a7c15u);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9u;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebu;
    return z ^ (z >> 31);
  }
  std::uint32_t Bits() { return static_cast<std::uint32_t>(Next() >> 32); }
  int Between(int low, int high) { return low + static_cast<int>(Next() % static_cast<std::uint64_t>(high - low + 1)); }
  // A float of either sign with a random mantissa and a power of two in [2^low, 2^high].
  float Scaled(int low, int high) {
    const std::uint32_t field = static_cast<std::uint32_t>(Between(low, high) + 127);
    return std::bit_cast<float>((Bits() & 0x807fffffu) | (field << 23));
  }

 private:
  std::uint64_t state_;
};

class Checker {
 public:
  void Check(float a, float b, float c) {
    const float got = std::fmaf(a, b, c), want = ExactFmaf(a, b, c);
    const std::uint32_t bits = std::isnan(got) ? 0x7fc00000u : std::bit_cast<std::uint32_t>(got);
    const bool same = std::isnan(want) ? std::isnan(got) : bits == std::bit_cast<std::uint32_t>(want);
    if (!same && result_.mismatches++ == 0) {
      result_.first_bad[0] = a;
      result_.first_bad[1] = b;
      result_.first_bad[2] = c;
    }
    for (int byte = 0; byte < 4; ++byte)
      result_.digest = (result_.digest ^ ((bits >> (8 * byte)) & 0xff)) * 0x100000001b3u;
    ++result_.cases;
  }
  const FmafCheck& result() const { return result_; }

 private:
  FmafCheck result_{0, 0, 0xcbf29ce484222325u, {0, 0, 0}};
};

// Products that are float midpoints (an odd 25-bit integer times a power of two: ma * k with k
// odd), alone and nudged by a c from a quarter ulp down to far below a double's last bit, where
// rounding to double first would land on the midpoint and then round it to even.
void MidpointCases(Checker& check, Random& random) {
  for (int k = 3; k <= 255; k += 2) {
    const std::uint32_t low = ((1u << 24) + static_cast<std::uint32_t>(k) - 1) / static_cast<std::uint32_t>(k);
    const std::uint32_t high = ((1u << 25) - 1) / static_cast<std::uint32_t>(k);
    for (int n = 0; n < 40; ++n) {
      const std::uint32_t ma = (low + static_cast<std::uint32_t>(random.Next() % (high - low + 1))) | 1u;
      if (ma > high || ma >= (1u << 24)) continue;
      const int ea = random.Between(-60, 40), eb = random.Between(-60, 40);
      const float a = std::ldexp(static_cast<float>(ma), ea) * (random.Bits() & 1 ? -1.0f : 1.0f);
      const float b = std::ldexp(static_cast<float>(k), eb);
      const int product_exponent = ea + eb + 24;  // the midpoint's top bit
      check.Check(a, b, 0.0f);
      check.Check(a, b, -0.0f);
      for (int below = 26; below <= 90; below += 4) {
        const float c = random.Scaled(product_exponent - below, product_exponent - below);
        check.Check(a, b, c);
        check.Check(a, b, -c);
      }
    }
  }
}

// Signed zeros, exact cancellation, overflow, underflow to subnormals and zero, infinities, NaN.
void EdgeCases(Checker& check, Random& random) {
  const float inf = std::numeric_limits<float>::infinity(), nan = std::numeric_limits<float>::quiet_NaN();
  const float max = std::numeric_limits<float>::max(), tiny = std::numeric_limits<float>::denorm_min();
  const float values[] = {0.0f,
                          -0.0f,
                          1.0f,
                          -1.0f,
                          3.0f,
                          -15.0f,
                          15.0f,
                          max,
                          -max,
                          tiny,
                          -tiny,
                          std::ldexp(1.0f, -75),
                          std::ldexp(1.5f, -75),
                          std::ldexp(1.0f, 103),
                          std::ldexp(1.0f, -126),
                          2.0f,
                          5.0f,
                          inf,
                          -inf,
                          nan};
  for (float a : values) {
    for (float b : values) {
      for (float c : values) check.Check(a, b, c);
    }
  }
  for (int n = 0; n < 20000; ++n) {
    // Each draw its own statement: a call's arguments are evaluated in no fixed order, and every
    // build must draw the same triples.
    const float tiny_a = random.Scaled(-80, -60), tiny_b = random.Scaled(-80, -60);
    const float subnormal = std::bit_cast<float>(random.Bits() & 0x807fffffu);
    check.Check(tiny_a, tiny_b, subnormal);  // results among the subnormals
    const float big_a = random.Scaled(60, 70), big_b = random.Scaled(55, 64), big_c = random.Scaled(120, 127);
    check.Check(big_a, big_b, big_c);  // overflow, or not quite
  }
}

}  // namespace

float ExactFmaf(float a, float b, float c) {
  if (!std::isfinite(a) || !std::isfinite(b) || !std::isfinite(c)) return SpecialFmaf(a, b, c);
  const Term ta = Decompose(a), tb = Decompose(b), tc = Decompose(c);
  Term product{ta.negative != tb.negative, ta.magnitude * tb.magnitude, ta.exponent + tb.exponent};
  if (product.magnitude == 0 && tc.magnitude == 0) {
    // An exact zero sum: -0 only when both are -0 (to nearest).
    return std::bit_cast<float>(product.negative && tc.negative ? 0x80000000u : 0u);
  }
  if (product.magnitude == 0) return c;
  if (tc.magnitude == 0) return RoundToFloat(product.negative, product.magnitude, product.exponent);
  // Align both on the exponent that puts the larger term's top bit at 125: the sum fits in 127 bits.
  const Term& high = TopBit(product.magnitude) + product.exponent >= TopBit(tc.magnitude) + tc.exponent ? product : tc;
  const Term& low = &high == &product ? tc : product;
  const int exponent = high.exponent - (125 - TopBit(high.magnitude));
  const Int128 h = static_cast<Int128>(ShiftSticky(high.magnitude, high.exponent - exponent));
  const Int128 l = static_cast<Int128>(ShiftSticky(low.magnitude, low.exponent - exponent));
  const Int128 sum = high.negative == low.negative ? h + l : h - l;
  if (sum == 0) return 0.0f;  // exact cancellation is +0 to nearest
  const bool negative = (sum < 0) != high.negative;
  return RoundToFloat(negative, static_cast<Uint128>(sum < 0 ? -sum : sum), exponent);
}

FmafCheck CheckFmaf(std::uint32_t seed, std::uint32_t random_cases) {
  Random random(seed);
  Checker check;
  for (std::uint32_t i = 0; i < random_cases; ++i) {
    switch (i % 3) {
      case 0:  // the fused rows' ranges: viewport scales and offsets, depth gradients and positions
      {
        const float a = random.Scaled(-24, 24), b = random.Scaled(-24, 24), c = random.Scaled(-24, 24);
        check.Check(a, b, c);
        break;
      }
      case 1:  // any bit pattern
      {
        const float a = std::bit_cast<float>(random.Bits()), b = std::bit_cast<float>(random.Bits());
        const float c = std::bit_cast<float>(random.Bits());
        check.Check(a, b, c);
        break;
      }
      default: {  // near cancellation: c within a few ulps of -a * b
        const float a = random.Scaled(-24, 24), b = random.Scaled(-24, 24);
        const float rounded = static_cast<float>(static_cast<double>(a) * b);
        const std::uint32_t nudged = std::bit_cast<std::uint32_t>(-rounded) + (random.Bits() % 7) - 3;
        check.Check(a, b, std::bit_cast<float>(nudged));
      }
    }
  }
  MidpointCases(check, random);
  EdgeCases(check, random);
  return check.result();
}

}  // namespace twinraster::page_module
