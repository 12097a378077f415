#include "verify/coverage_judgement.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

namespace twinraster::verify {

Judgement JudgementOf(const CoverageVerification& c) {
  if (c.work.Exceeded()) return Judgement::kInconclusive;
  if (c.Violations() > 0) return Judgement::kFailed;
  if (c.certainly_covered <= c.holes_allowed || c.certainly_uncovered == 0) return Judgement::kInconclusive;
  if (2 * c.uncertain >= c.certainly_covered + c.uncertain) return Judgement::kInconclusive;
  return Judgement::kPassed;
}

CoverageVerification JudgeCoverage(const Verification& v, const Image& image, Rgb8 scene_background,
                                   const CoverageOptions& options) {
  if (image.width != v.width || image.height != v.height) {
    throw std::invalid_argument("the verification is of a " + std::to_string(v.width) + " x " +
                                std::to_string(v.height) + " image, not this one");
  }
  if (v.reach.size() != std::size_t{v.width} * v.height) {
    throw std::invalid_argument("the verification has no reach (VerifyOptions::reach was not set)");
  }
  if (!(options.hole_tolerance_percent >= 0 && options.hole_tolerance_percent <= 100)) {
    throw std::invalid_argument("the hole tolerance must be 0 to 100 %");
  }
  CoverageVerification c;
  c.width = v.width, c.height = v.height, c.rules = v.options;
  c.background = options.background.value_or(scene_background);
  c.background_given = options.background.has_value();
  c.hole_tolerance_percent = options.hole_tolerance_percent;
  c.work = v.work;
  c.pixels.resize(v.reach.size());
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::size_t i = std::size_t{y} * image.width + x;
      const std::uint8_t* p = image.pixel(x, y);
      const Rgb8 colour{p[0], p[1], p[2]};  // alpha is not read: engines write it many ways
      const bool covered = !(colour == c.background);
      c.image_covered += covered;
      CoveragePixel& out = c.pixels[i];
      switch (v.reach[i]) {
        case Reach::kMaybe:
          ++c.uncertain;
          c.uncertain_covered += covered;
          out = CoveragePixel::kFree;
          break;
        case Reach::kNone:
          ++c.certainly_uncovered;
          out = covered ? CoveragePixel::kSpill : CoveragePixel::kAgrees;
          if (covered && ++c.spills == 1) c.first_spill = CoveragePosition{x, y, colour};
          break;
        case Reach::kCertain:
          ++c.certainly_covered;
          out = covered ? CoveragePixel::kAgrees : CoveragePixel::kHole;
          if (!covered && ++c.holes == 1) c.first_hole = CoveragePosition{x, y, colour};
          break;
      }
    }
  }
  c.holes_allowed =
      std::uint64_t(std::floor(double(c.certainly_covered) * options.hole_tolerance_percent / 100.0 + 1e-9));
  if (c.holes > 0 && c.HolesWithin()) {
    for (CoveragePixel& p : c.pixels) {
      if (p == CoveragePixel::kHole) p = CoveragePixel::kHoleWithin;
    }
  }
  return c;
}

Image CoverageMap(const Image& image, const CoverageVerification& c) {
  if (image.width != c.width || image.height != c.height) {
    throw std::invalid_argument("the coverage judgement is of a " + std::to_string(c.width) + " x " +
                                std::to_string(c.height) + " image, not this one");
  }
  Image map(image.width, image.height, Image::Uncleared{});  // every pixel is written below
  for (std::size_t i = 0; i < c.pixels.size(); ++i) {
    const std::uint8_t* in = image.rgba.data() + 4 * i;
    std::uint8_t* out = map.rgba.data() + 4 * i;
    const int luma = (54 * in[0] + 183 * in[1] + 19 * in[2]) >> 8;  // Rec. 709 weights, as verify_map's
    const int grey = 128 + luma / 2;
    out[3] = 255;
    switch (c.pixels[i]) {
      case CoveragePixel::kAgrees: out[0] = out[1] = out[2] = std::uint8_t(grey); break;
      case CoveragePixel::kFree:  // amber (255, 176, 0), two thirds of the way from the grey
        out[0] = std::uint8_t((grey + 2 * 255) / 3), out[1] = std::uint8_t((grey + 2 * 176) / 3);
        out[2] = std::uint8_t(grey / 3);
        break;
      case CoveragePixel::kSpill: out[0] = 255, out[1] = 0, out[2] = 0; break;
      case CoveragePixel::kHole: out[0] = 0, out[1] = 64, out[2] = 255; break;
      case CoveragePixel::kHoleWithin: out[0] = 0, out[1] = 200, out[2] = 255; break;
    }
  }
  return map;
}

}  // namespace twinraster::verify
