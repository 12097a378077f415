// What the verifier concludes about an image: per pixel certain, uncertain or a violation, the
// counts, and the worst violation with the colours allowed there. Every output (text, JSON, map,
// render's sentence) reads this one record.
#pragma once

#include "verify/allowed_colours.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::verify {

enum class PixelClass : std::uint8_t {
  kCertain,    // only one surface (or only the background) can show here, and the image shows it
  kUncertain,  // more than one can, and the image shows one of them
  kViolation,  // the image's colour is not one a conformant implementation may write here
};

struct Violation {
  std::uint32_t x = 0, y = 0;
  Rgb8 colour;
  int distance = 0;                  // channel steps from the nearest allowed colour
  std::vector<ColourRange> allowed;  // what each surface (or the background) that may show here allows
};

struct VerifyOptions {
  // subPixelPrecisionBits of the device that drew the image; the spec's minimum by default.
  int subpixel_bits = 4;
};

struct Verification {
  std::uint32_t width = 0, height = 0;
  int subpixel_bits = 4;
  std::vector<PixelClass> pixels;  // row by row, top first
  std::uint64_t certain = 0, uncertain = 0, violations = 0;
  std::uint64_t covered = 0;  // pixels where some surface may show (the background is not certain)
  std::optional<Violation> worst;
  std::optional<Violation> first;  // in row order

  bool Passed() const { return violations == 0; }
  double UncertainFraction() const { return covered ? double(uncertain) / double(covered) : 0.0; }
};

// "passes: 21503 px certain, 97 uncertain (0.45 % of the 21600 covered), 0 violations" or
// "fails: 12 violations, worst at (x, y): ..."
std::string VerificationText(const Verification& v);
// "(12, 40..42, 200)"
std::string RangeText(const ColourRange& range);

}  // namespace twinraster::verify
