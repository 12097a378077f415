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

Judgement Verification::Verdict() const {
  if (violations > 0) return Judgement::kFailed;
  if (background_excluded == 0 || 2 * UncertainOther() >= covered) return Judgement::kInconclusive;
  return Judgement::kPassed;
}

}  // namespace twinraster::verify
