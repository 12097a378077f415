// `verify --coverage`: judges only where an image is covered, for engines whose shading twinraster
// does not model. Each pixel is read as the clear colour (background) or anything else (covered),
// and held against the verifier's Reach (verification.hpp). It does not judge colours or depth
// order, and computes no geometry: the verifier does (VerifyImage with VerifyOptions::reach).
#pragma once

#include "image/image.hpp"
#include "scene/scene.hpp"
#include "verify/verification.hpp"

#include <cstdint>
#include <optional>
#include <vector>

namespace twinraster::verify {

// One pixel's coverage class; the map draws each class in its own colour.
enum class CoveragePixel : std::uint8_t {
  kAgrees,     // certainly covered and covered, or certainly uncovered and background
  kFree,       // some primitive may cover it, none certainly does: either reading is allowed
  kSpill,      // covered (not the clear colour) where no primitive may reach: always a violation
  kHole,       // the clear colour where a primitive certainly covers: a violation beyond the tolerance
  kHoleWithin  // such a pixel, while the holes are within the tolerance (shading may give the clear colour)
};

struct CoverageOptions {
  VerifyOptions rules;  // the device's rasterization (subpixel bits, strict lines), as verify's
  // The clear colour the engine used, compared in R, G and B exactly; the scene's background when unset.
  std::optional<Rgb8> background;
  // Holes allowed, as a percentage of the pixels certainly covered, for an engine whose shading
  // may produce the clear colour. 0 (the default): any hole fails; docs/verify.md advises a clear
  // colour shading cannot produce rather than a tolerance.
  double hole_tolerance_percent = 0;
};

struct CoveragePosition {
  std::uint32_t x = 0, y = 0;
  Rgb8 colour;  // the image's colour there
};

struct CoverageVerification {
  std::uint32_t width = 0, height = 0;
  VerifyOptions rules;
  Rgb8 background;                // the clear colour judged by
  bool background_given = false;  // by CoverageOptions::background, not the scene
  double hole_tolerance_percent = 0;
  std::vector<CoveragePixel> pixels;  // row by row, top first
  // What the verifier says of each pixel; the three add up to width x height.
  std::uint64_t certainly_covered = 0, certainly_uncovered = 0, uncertain = 0;
  std::uint64_t image_covered = 0;      // pixels of the image not the clear colour
  std::uint64_t uncertain_covered = 0;  // of the uncertain pixels, those the image covers
  std::uint64_t spills = 0, holes = 0;
  std::uint64_t holes_allowed = 0;                          // floor(tolerance % of certainly_covered)
  std::optional<CoveragePosition> first_spill, first_hole;  // in row order
  WorkBudget work;                                          // the verification's: exceeded, nothing was judged

  // Spills, and holes when there are more than holes_allowed.
  std::uint64_t Violations() const { return spills + (HolesWithin() ? 0 : holes); }
  bool HolesWithin() const { return holes <= holes_allowed; }
};

// The judgement of the image's coverage. Inconclusive when the verifier's work was over budget.
// Failed on any violation. Inconclusive when an image with
// nothing covered would pass (no pixel is certainly covered beyond the holes allowed), when one
// covered everywhere would (no pixel is certainly uncovered), or when the uncertain pixels are at
// least half of those some primitive may cover: such a judgement cannot tell a transform bug from a
// correct image.
Judgement JudgementOf(const CoverageVerification& coverage);

// `verification` must come from VerifyImage of this image with VerifyOptions::reach; `scene_background`
// is the scene's clear colour, used unless the options give one. Throws std::invalid_argument when
// the sizes differ, the reach is missing, or the tolerance is not within 0..100.
CoverageVerification JudgeCoverage(const Verification& verification, const Image& image, Rgb8 scene_background,
                                   const CoverageOptions& options);

// The coverage map: the image's luminance faded halfway to white where a pixel agrees, amber where
// it is free, red (255, 0, 0) for a spill, blue (0, 64, 255) for a hole that counts, cyan (0, 200,
// 255) for a hole within the tolerance.
Image CoverageMap(const Image& image, const CoverageVerification& coverage);

}  // namespace twinraster::verify
