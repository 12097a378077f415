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

// Whether any primitive may cover a pixel's centre and pass the depth test against the clear
// value, whatever the image shows: what coverage.hpp judges an image's coverage by.
enum class Reach : std::uint8_t {
  kNone,     // no primitive may (the background certainly shows)
  kMaybe,    // some may, none certainly does (an edge within the device's snapping, a depth near a plane)
  kCertain,  // some primitive certainly covers it (pass 1 found one)
};

struct Violation {
  std::uint32_t x = 0, y = 0;
  Rgb8 colour;
  int distance = 0;                  // channel steps from the nearest allowed colour
  std::vector<ColourRange> allowed;  // what each surface (or the background) that may show here allows
};

// What the verifier concludes about the image as a whole.
enum class Judgement : std::uint8_t {
  kPassed,        // no violation, and the certain pixels could have caught a broken image
  kInconclusive,  // no violation, but too little is certain to tell a correct image from a broken one
  kFailed,        // some pixel has a colour no conformant implementation may write there
};
const char* JudgementName(Judgement judgement);  // "passed", "inconclusive", "failed"

// How the device that drew the image rasterizes, as it reports (limits of VkPhysicalDeviceLimits);
// the spec's loosest values by default, which judge any device's image but certify less.
struct VerifyOptions {
  int subpixel_bits = 4;      // subPixelPrecisionBits; the spec's minimum is 4
  bool strict_lines = false;  // strictLines
  // Not the device's: whether the verifier skips the draws, and the runs of a tile's pixels, where
  // a surface's box and depth range show it cannot matter. The judgement is the same either way;
  // false (every one tested) is for the tests that check so.
  bool fast_paths = true;
  // Not the device's either: whether Verification::reach is filled (verify --coverage reads it).
  bool reach = false;
  // The most pixel tests (work_estimate.hpp) the verifier makes; a scene estimated above it is
  // judged inconclusive without a pixel judged. 2^31 (2.1e9): 13x the most any shipped scene
  // needs (one-million-cubes, 1.7e8, judged in 3 s), so well under a minute (docs/verify.md).
  std::uint64_t pixel_test_budget = std::uint64_t{1} << 31;
};

// The verifier's work, estimated before it starts, against the budget it was held to.
struct WorkBudget {
  std::uint64_t pixel_tests = 0, budget = 0;
  bool Exceeded() const { return pixel_tests > budget; }
};

struct Verification {
  std::uint32_t width = 0, height = 0;
  VerifyOptions options;
  std::vector<PixelClass> pixels;  // row by row, top first
  std::uint64_t certain = 0, uncertain = 0, violations = 0;
  std::uint64_t covered = 0;  // pixels where some surface may show (the background is not certain)
  // Uncertain pixels that lines certain to cover them all cover, with depths too close to order:
  // coinciding edges of different colours, as where a cube's faces meet (wireframes only).
  std::uint64_t uncertain_shared_edges = 0;
  // Pixels where the background's colour is not allowed: where an empty image would fail.
  std::uint64_t background_excluded = 0;
  std::optional<Violation> worst;
  std::optional<Violation> first;  // in row order
  std::vector<Reach> reach;        // row by row, when VerifyOptions::reach asks; else empty
  WorkBudget work;                 // exceeded: no pixel was judged (all uncertain, reach all maybe)

  bool NoViolations() const { return violations == 0; }
  std::uint64_t UncertainOther() const { return uncertain - uncertain_shared_edges; }
  double UncertainFraction() const { return covered ? double(uncertain) / double(covered) : 0.0; }
};

// The judgement of the whole image (a run's verdict is run/verdict.hpp's, made from it).
// Inconclusive when the work was over budget (nothing was judged). Failed on any violation. Inconclusive when an empty
// image would pass as well, or when the uncertain pixels, less those of shared edges, are half the covered pixels or
// more (a broken image then mostly passes too: docs/verify.md, "Passed, failed or inconclusive").
Judgement JudgementOf(const Verification& verification);

}  // namespace twinraster::verify
