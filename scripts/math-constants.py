#!/usr/bin/python3
"""Derives the constants of the project's own trigonometry (src/base/trigonometry.cpp) and sRGB
bytes (src/scene/srgb.cpp), in 60-digit decimal arithmetic, and prints them as C++:

- pi (Machin's formula, pi/4 = 4 atan(1/5) - atan(1/239)), then pi/180 and pi/2, each as a double
  hi and a double lo with hi + lo within 2^-106 of the true value, and a third part of pi/180;
- the first term the Taylor series of sin and cos leave out, against the sum, for |x| <= pi/4;
- the 255 linear values at which sRGB's byte goes up by one: the smallest double at or above the
  real c where 255 * encode(c) = k + 0.5, for k = 0 .. 254 (encode is IEC 61966-2-1's transfer
  function: 12.92 c up to 0.0031308, 1.055 c^(1/2.4) - 0.055 above). A byte is then the count of
  these at or below c: exact, with no power computed at run time.

Usage: math-constants.py"""
import math
from decimal import Decimal, getcontext

getcontext().prec = 60


def arctan_of_inverse(n):
    """atan(1/n) by its Taylor series, to 70 decimal places."""
    x = Decimal(1) / n
    total, term, k, sign = Decimal(0), x, 1, 1
    while term > Decimal(10) ** -70:
        total += sign * term / k
        term *= x * x
        k, sign = k + 2, -sign
    return total


def split(value):
    """value as hi + lo, each the double nearest what is left."""
    hi = float(value)
    return hi, float(value - Decimal(hi))


def series_bounds(pi):
    """The first left-out term of sin (to x^25) and cos (to x^26) at pi/4, against the sum."""
    x, sin_and_cos = pi / 4, Decimal(2).sqrt() / 2  # the ratios are largest at pi/4
    return (float(x ** 27 / math.factorial(27) / sin_and_cos),
            float(x ** 28 / math.factorial(28) / sin_and_cos))


def srgb_threshold(k):
    """The smallest double c with 255 encode(c) >= k + 0.5."""
    target = (Decimal(k) + Decimal("0.5")) / 255
    linear = target / Decimal("12.92")
    if linear > Decimal("0.0031308"):
        linear = ((target + Decimal("0.055")) / Decimal("1.055")) ** Decimal("2.4")
    c = float(linear)
    if Decimal(c) < linear:
        c = math.nextafter(c, 2.0)
    assert abs(Decimal(c) - linear) > Decimal(10) ** -40, "too close to call at 60 digits"
    return c


def main():
    pi = 16 * arctan_of_inverse(5) - 4 * arctan_of_inverse(239)
    for name, value in (("kRadiansPerDegree", pi / 180), ("kHalfPi", pi / 2)):
        hi, lo = split(value)
        print(f"constexpr Double2 {name} = {{{hi.hex()}, {lo.hex()}}};  // {hi!r} + {lo!r}")
    hi, lo = split(pi / 180)
    rest = float(pi / 180 - Decimal(hi) - Decimal(lo))
    print(f"constexpr double kRadiansPerDegreeRest = {rest.hex()};  // {rest!r}")
    sin_left, cos_left = series_bounds(pi)
    print(f"// left out at pi/4: sin {sin_left:.3g} (2^{math.log2(sin_left):.1f}), "
          f"cos {cos_left:.3g} (2^{math.log2(cos_left):.1f}) of the sum")
    thresholds = [srgb_threshold(k) for k in range(255)]
    print("constexpr std::array<double, 255> kByteStarts = {")
    for row in range(0, 255, 4):
        print("    " + " ".join(f"{c!r}," for c in thresholds[row:row + 4]))
    print("};")


if __name__ == "__main__":
    main()
