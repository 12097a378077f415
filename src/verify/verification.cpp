#include "verify/verification.hpp"

namespace twinraster::verify {

const char* JudgementName(Judgement judgement) {
  switch (judgement) {
    case Judgement::kPassed: return "passed";
    case Judgement::kInconclusive: return "inconclusive";
    case Judgement::kFailed: return "failed";
  }
  return "failed";
}

Judgement JudgementOf(const Verification& v) {
  if (v.work.Exceeded()) return Judgement::kInconclusive;
  if (v.violations > 0) return Judgement::kFailed;
  if (v.background_excluded == 0 || 2 * v.UncertainOther() >= v.covered) return Judgement::kInconclusive;
  return Judgement::kPassed;
}

}  // namespace twinraster::verify
