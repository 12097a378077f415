#include "base/trigonometry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

// The method. An angle in degrees is reduced to |t| ≤ 45° exactly (fmod by 360 is exact, and so is
// t = r - 90·n), turned into radians as a double-double x = t·π/180, and sin x and cos x are the
// Taylor series, summed in double-double: sin x = x·(1 - z/(2·3)·(1 - z/(4·5)·(1 - ...))),
// cos x = 1 - z/(1·2)·(1 - z/(3·4)·(1 - ...)), z = x². Each nesting step divides by the ratio of
// two consecutive factorials, so the series needs no table of coefficients. A double-double holds a
// number as hi + lo (about 106 bits), with Dekker's exact product and Knuth's exact sum (Dekker,
// "A floating-point technique for extending the available precision", 1971; Knuth, TAOCP vol. 2,
// 4.2.2), written without a fused multiply-add. The result, rounded once at the end, is off by
// 0.5 ulp plus about 2^-50 ulp: wrong only when the true value lies that close to a midpoint
// between two doubles. scripts/math-constants.py derives π/180's two parts and the series' bound;
// tests/base/trigonometry_test.cpp measures all of it against quadruple precision.
namespace twinraster {
namespace {

// hi + lo, |lo| ≤ ulp(hi)/2.
struct Double2 {
  double hi;
  double lo;
};

// Knuth's two-sum: s + e == a + b exactly, for any a and b.
Double2 TwoSum(double a, double b) {
  const double s = a + b;
  const double b_part = s - a;
  const double e = (a - (s - b_part)) + (b - b_part);
  return {s, e};
}

// Dekker's fast two-sum: exact when |a| ≥ |b| (or a == 0).
Double2 FastTwoSum(double a, double b) {
  const double s = a + b;
  return {s, b - (s - a)};
}

// Veltkamp's split: a == hi + lo with 26 bits each, so that their products are exact.
Double2 Split(double a) {
  const double t = 134217729.0 * a;  // 2^27 + 1
  const double hi = t - (t - a);
  return {hi, a - hi};
}

// Dekker's product: p + e == a · b exactly (no fused multiply-add: the project compiles with
// -ffp-contract=off, and a contracted product would round differently).
Double2 TwoProduct(double a, double b) {
  const double p = a * b;
  const Double2 x = Split(a), y = Split(b);
  const double e = ((x.hi * y.hi - p) + x.hi * y.lo + x.lo * y.hi) + x.lo * y.lo;
  return {p, e};
}

Double2 Add(Double2 a, Double2 b) {
  const Double2 s = TwoSum(a.hi, b.hi);
  return FastTwoSum(s.hi, s.lo + (a.lo + b.lo));
}

Double2 Negate(Double2 a) { return {-a.hi, -a.lo}; }

Double2 Multiply(Double2 a, Double2 b) {
  const Double2 p = TwoProduct(a.hi, b.hi);
  return FastTwoSum(p.hi, p.lo + (a.hi * b.lo + a.lo * b.hi));
}

// a / b: the first quotient's remainder, exact by Dekker's product, gives the second.
Double2 Divide(Double2 a, Double2 b) {
  const double q = a.hi / b.hi;
  const Double2 remainder = Add(a, Negate(Multiply(b, {q, 0.0})));
  return FastTwoSum(q, remainder.hi / b.hi);
}

// π/180 and π/2 as hi + lo, and what π/180 leaves beyond them (scripts/math-constants.py).
constexpr Double2 kRadiansPerDegree = {0x1.1df46a2529d39p-6, 0x1.5c1d8becdd291p-62};
constexpr double kRadiansPerDegreeRest = -0x1.1d937fa428858p-116;
constexpr Double2 kHalfPi = {0x1.921fb54442d18p+0, 0x1.1a62633145c07p-54};

// 1 - z/(f·(f+1))·(1 - z/((f+2)·(f+3))·(1 - ...)), `terms` nestings, innermost first. For
// |x| ≤ π/4 the first term left out is below 2^-100 of the sum (scripts/math-constants.py).
Double2 NestedSeries(Double2 z, int first_factor, int terms) {
  Double2 sum = {1.0, 0.0};
  for (int k = terms - 1; k >= 0; --k) {
    const double f = first_factor + 2 * k;
    sum = Add({1.0, 0.0}, Negate(Divide(Multiply(z, sum), {f * (f + 1), 0.0})));
  }
  return sum;
}

// sin x to x^25/25!, cos x to x^26/26!, for |x| ≤ π/4 (a hair more is harmless).
Double2 SineOf(Double2 x) { return Multiply(x, NestedSeries(Multiply(x, x), 2, 12)); }
Double2 CosineOf(Double2 x) { return NestedSeries(Multiply(x, x), 1, 13); }

// t° in radians, to about 2^-104 of it.
Double2 Radians(double t) {
  const Double2 p = TwoProduct(t, kRadiansPerDegree.hi);
  return FastTwoSum(p.hi, p.lo + t * kRadiansPerDegree.lo);
}

// sin and cos of degrees°, in double-double. Both reduction steps are exact: fmod always is, and
// t is a multiple of r's ulp no larger than r.
struct Turned {
  Double2 sine;
  Double2 cosine;
};
Turned OfDegrees(double degrees) {
  // An infinity or a NaN has no quarter turn to count (converting its NaN to int is undefined).
  if (!std::isfinite(degrees)) {
    const Double2 nan{std::numeric_limits<double>::quiet_NaN(), 0.0};
    return {nan, nan};
  }
  const double r = std::fmod(degrees, 360.0);
  const double n = std::nearbyint(r / 90.0);
  const Double2 x = Radians(r - 90.0 * n);
  const Double2 s = SineOf(x), c = CosineOf(x);
  switch ((static_cast<int>(n) % 4 + 4) % 4) {  // the quarter turns in r
    case 0: return {s, c};
    case 1: return {c, Negate(s)};
    case 2: return {Negate(s), Negate(c)};
    default: return {Negate(c), s};
  }
}

}  // namespace

SineCosine SineCosineOfDegrees(double degrees) {
  const Turned at = OfDegrees(degrees);
  SineCosine result = {at.sine.hi, at.cosine.hi};
  // IEEE 754's sinPi and cosPi: an exact zero sine keeps the angle's sign, an exact zero cosine is +0.
  if (result.sine == 0) result.sine = std::copysign(0.0, degrees);
  if (result.cosine == 0) result.cosine = 0.0;
  return result;
}

SineCosine SineCosineOfRoundedRadians(double degrees) {
  const double radians = degrees * std::numbers::pi / 180.0;  // the demos' argument, rounded twice
  // radians = θ·π/180 + δ, δ a few ulps of radians: sin(θ° + δ) and cos(θ° + δ) by the sum formulas.
  // δ is found to about 2^-150 of radians (π/180 in three parts), for where sin θ° is 0 and δ is all.
  const Double2 first = TwoProduct(degrees, kRadiansPerDegree.hi), second = TwoProduct(degrees, kRadiansPerDegree.lo);
  Double2 delta = {radians - first.hi, 0.0};  // exact: the two are within a few ulps
  for (const double part : {first.lo, second.hi, second.lo, degrees * kRadiansPerDegreeRest})
    delta = Add(delta, {-part, 0.0});
  const Turned at = OfDegrees(degrees);
  const Double2 sin_delta = SineOf(delta), cos_delta = CosineOf(delta);
  return {Add(Multiply(at.sine, cos_delta), Multiply(at.cosine, sin_delta)).hi,
          Add(Multiply(at.cosine, cos_delta), Negate(Multiply(at.sine, sin_delta))).hi};
}

double TangentOfRadians(double radians) {
  const double a = std::fabs(radians);
  if (a <= kHalfPi.hi / 2) return Divide(SineOf({radians, 0.0}), CosineOf({radians, 0.0})).hi;
  // tan a = cos y / sin y with y = π/2 - a ≤ π/4: kHalfPi.hi - a is exact (Sterbenz's lemma).
  const Double2 y = FastTwoSum(kHalfPi.hi - a, kHalfPi.lo);
  return std::copysign(Divide(CosineOf(y), SineOf(y)).hi, radians);
}

double Hypotenuse(double x, double y, double z) {
  x = std::fabs(x), y = std::fabs(y), z = std::fabs(z);
  const double largest = std::max({x, y, z});
  if (largest == 0 || !(std::isfinite(x) && std::isfinite(y) && std::isfinite(z))) return x + y + z;
  // Scaled by a power of two, exactly, so that the largest is in [0.5, 1): no square overflows,
  // and any that underflows is too small to count.
  int exponent = 0;
  std::frexp(largest, &exponent);
  x = std::ldexp(x, -exponent), y = std::ldexp(y, -exponent), z = std::ldexp(z, -exponent);
  return std::ldexp(std::sqrt(x * x + y * y + z * z), exponent);
}

}  // namespace twinraster
