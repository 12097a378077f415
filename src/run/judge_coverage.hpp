// `verify --coverage`'s run, callable from C++: an image of a scene, drawn by any engine with its own
// shading, judged only by where it is covered (verify/coverage_judgement.hpp), with the verdict
// every output and exit code reads. It reads no file and writes nothing; cli/ hands it the image and
// the options (the device's rules from the image's notes or the command line, the clear colour).
//
//   const run::CoverageJudgement j = run::JudgeCoverage(scene, image, {.background = Rgb8{255, 0, 255}});
//   if (j.verdict == run::Verdict::kDiffering) ...  // j.coverage.spills, j.coverage.holes, first_spill
//
// Pass pixels the engine drew single-sampled, at the scene's canvas size and camera, with a clear
// colour its shading never produces (docs/verify.md, "Judging coverage only").
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "run/verdict.hpp"
#include "scene/scene.hpp"
#include "verify/coverage_judgement.hpp"

#include <cstdint>
#include <optional>

namespace twinraster::run {

struct CoverageJudgement {
  verify::CoverageVerification coverage;
  double verify_ms = 0;
  std::optional<Image> map;              // when asked for (verify::CoverageMap)
  Verdict verdict = Verdict::kVerified;  // kVerified, kInconclusive or kDiffering
  std::uint64_t not_opaque = 0;          // pixels whose alpha is not 255: alpha is not judged
};

// Throws std::invalid_argument when the image is not the scene's canvas size, or an option is out
// of range (subpixel bits 0..24, tolerance 0..100 %).
CoverageJudgement JudgeCoverage(const Scene& scene, const Image& image, const verify::CoverageOptions& options = {},
                                bool map = false);
// The same, for a caller that already has the scene's draw list (BuildDrawList(scene)).
CoverageJudgement JudgeCoverage(const Scene& scene, const DrawList& list, const Image& image,
                                const verify::CoverageOptions& options = {}, bool map = false);

}  // namespace twinraster::run
