#include "run/judge_coverage.hpp"

#include "base/stopwatch.hpp"
#include "verify/verifier.hpp"

namespace twinraster::run {

CoverageJudgement JudgeCoverage(const Scene& scene, const Image& image, const verify::CoverageOptions& options,
                                bool map) {
  return JudgeCoverage(scene, BuildDrawList(scene), image, options, map);
}

CoverageJudgement JudgeCoverage(const Scene& scene, const DrawList& list, const Image& image,
                                const verify::CoverageOptions& options, bool map) {
  CoverageJudgement j;
  Stopwatch clock;
  verify::VerifyOptions rules = options.rules;
  rules.reach = true;
  // The verifier's colour judgement comes along; only its reach is read here.
  const verify::Verification verification = verify::VerifyImage(scene, list, image, rules);
  j.coverage = verify::JudgeCoverage(verification, image, scene.canvas.background, options);
  j.coverage.rules.reach = false;  // the device's rules, as given
  j.verify_ms = clock.Milliseconds();
  if (map) j.map = verify::CoverageMap(image, j.coverage);
  j.verdict = VerdictOf(verify::JudgementOf(j.coverage));
  j.not_opaque = NotOpaquePixels(image);
  return j;
}

}  // namespace twinraster::run
