#include "run/judge_image.hpp"

#include "base/stopwatch.hpp"
#include "chain/draw_list.hpp"
#include "verify/verifier.hpp"
#include "verify/verify_map.hpp"

namespace twinraster::run {

ImageJudgement JudgeImage(const Scene& scene, const Image& image, const verify::VerifyOptions& rules, bool map) {
  const DrawList list = BuildDrawList(scene);
  ImageJudgement j;
  Stopwatch clock;
  j.verification = verify::VerifyImage(scene, list, image, rules);
  j.verify_ms = clock.Milliseconds();
  if (map) j.map = verify::VerificationMap(image, j.verification);
  switch (j.verification.Verdict()) {
    case verify::Judgement::kPassed: j.verdict = Verdict::kVerified; break;
    case verify::Judgement::kInconclusive: j.verdict = Verdict::kInconclusive; break;
    case verify::Judgement::kFailed: j.verdict = Verdict::kDiffering; break;
  }
  return j;
}

}  // namespace twinraster::run
