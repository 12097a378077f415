#include "run/judge_image.hpp"

#include "base/stopwatch.hpp"
#include "chain/draw_list.hpp"
#include "verify/verifier.hpp"
#include "verify/verify_map.hpp"

namespace twinraster::run {

ImageJudgement JudgeImage(const Scene& scene, const Image& image, const verify::VerifyOptions& rules, bool map) {
  return JudgeImage(scene, BuildDrawList(scene), image, rules, map);
}

ImageJudgement JudgeImage(const Scene& scene, const DrawList& list, const Image& image,
                          const verify::VerifyOptions& rules, bool map) {
  ImageJudgement j;
  Stopwatch clock;
  j.verification = verify::VerifyImage(scene, list, image, rules);
  j.verify_ms = clock.Milliseconds();
  if (map) j.map = verify::VerificationMap(image, j.verification);
  j.verdict = VerdictOf(verify::JudgementOf(j.verification));
  j.not_opaque = NotOpaquePixels(image);
  return j;
}

}  // namespace twinraster::run
