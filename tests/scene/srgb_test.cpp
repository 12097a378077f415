// sRGB bytes from linear colours: each of the 255 places where the byte goes up is where
// quadruple precision puts it, to the double, so every double gets the exact byte; and against
// the formula with glibc's std::pow, what differs is only within a few ulps of those places
// (printed: how many doubles, and how far).
#include "scene/srgb.hpp"

#include "support/catch.hpp"
#include "support/quad_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <vector>

using namespace twinraster;

namespace {

// The formula srgb.cpp computed before, with the C library's pow.
std::uint8_t PowByte(double linear) {
  const double c = std::clamp(std::isnan(linear) ? 0.0 : linear, 0.0, 1.0);
  const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
  return static_cast<std::uint8_t>(std::lround(std::clamp(encoded, 0.0, 1.0) * 255.0));
}

// The first double in [0, 1] whose byte is more than `byte` (SrgbByte never falls: checked below).
double ByteStart(int byte) {
  double low = 0, high = 1;  // SrgbByte(low) <= byte < SrgbByte(high)
  while (std::nextafter(low, 2.0) < high) {
    const double middle = low + (high - low) / 2;
    (SrgbByte(middle) > byte ? high : low) = middle;
  }
  return high;
}

// How many doubles apart two non-negative doubles are (their bits, as integers, are in order).
double UlpsApart(double a, double b) {
  std::uint64_t x, y;
  std::memcpy(&x, &a, sizeof x);
  std::memcpy(&y, &b, sizeof y);
  return static_cast<double>(x > y ? x - y : y - x);
}

std::vector<double> ByteStarts() {
  std::vector<double> starts;
  for (int k = 0; k < 255; ++k) starts.push_back(ByteStart(k));
  return starts;
}

#ifdef TWINRASTER_QUAD_REFERENCE
// 255 · encode(c) - (k + 0.5) in quadruple precision: its sign says which side of byte k's top c is.
test::Quad AboveTop(double c, int k) {
  using test::Quad;
  const Quad q = c;
  const Quad encoded = c <= 0.0031308 ? q * 1292 / 100 : test::powq(q, Quad(5) / 12) * 1055 / 1000 - Quad(55) / 1000;
  return encoded * 255 - (k + Quad(0.5));
}
#endif

}  // namespace

TEST_CASE("sRGB bytes: every step is where quadruple precision puts it") {
  const std::vector<double> starts = ByteStarts();
  for (int k = 0; k < 255; ++k) {
    const double start = starts[static_cast<std::size_t>(k)];
    INFO("byte " << k + 1 << " starts at " << start);
    REQUIRE(SrgbByte(start) == k + 1);  // one step at a time: no byte skipped
    REQUIRE(SrgbByte(std::nextafter(start, 0.0)) == k);
#ifdef TWINRASTER_QUAD_REFERENCE
    REQUIRE(AboveTop(start, k) >= 0);
    REQUIRE(AboveTop(std::nextafter(start, 0.0), k) < 0);
#endif
  }
  CHECK(SrgbByte(0.0) == 0);
  CHECK(SrgbByte(-1.0) == 0);
  CHECK(SrgbByte(1.0) == 255);
  CHECK(SrgbByte(2.0) == 255);
  CHECK(SrgbByte(std::numeric_limits<double>::infinity()) == 255);
  CHECK(SrgbByte(std::numeric_limits<double>::quiet_NaN()) == 0);
}

TEST_CASE("sRGB bytes: the same as std::pow's formula except within a few ulps of a step") {
  const std::vector<double> starts = ByteStarts();
  std::vector<double> inputs;
  for (const double start : starts) {  // 64 doubles either side of every step
    double below = start, above = start;
    for (int i = 0; i < 64; ++i) {
      below = std::nextafter(below, 0.0);
      inputs.push_back(below);
      inputs.push_back(above);
      above = std::nextafter(above, 2.0);
    }
  }
  for (int i = 0; i <= 65535; ++i) inputs.push_back(i / 65535.0);  // 8- and 16-bit normalized colours
  for (int i = 0; i <= 255; ++i) inputs.push_back(i / 255.0);
  for (std::uint32_t bits = 0; bits <= 0x3f800000u; bits += 97) {  // every 97th float in [0, 1]
    float f;
    std::memcpy(&f, &bits, sizeof f);
    inputs.push_back(f);
  }
  std::size_t differs = 0;
  double farthest = 0;  // ulps from the nearest step
  for (const double c : inputs) {
    if (SrgbByte(c) == PowByte(c)) continue;
    ++differs;
    const auto above = std::lower_bound(starts.begin(), starts.end(), c);
    double apart = above == starts.end() ? 1e300 : UlpsApart(c, *above);
    if (above != starts.begin()) apart = std::min(apart, UlpsApart(c, *(above - 1)));
    farthest = std::max(farthest, apart);
  }
  std::printf(
      "sRGB: %zu inputs (%zu around the 255 steps); std::pow's formula gives another byte on %zu, "
      "at most %.0f ulp from a step\n",
      inputs.size(), starts.size() * 128, differs, farthest);
  CHECK(farthest <= 8);
  std::uint8_t last = 0;  // and the byte never falls, over the inputs sorted
  std::sort(inputs.begin(), inputs.end());
  for (const double c : inputs) {
    REQUIRE(SrgbByte(c) >= last);
    last = SrgbByte(c);
  }
}
