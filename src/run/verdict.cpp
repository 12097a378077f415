#include "run/verdict.hpp"

#include "base/exit_code.hpp"

namespace twinraster::run {

const char* VerdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::kError: return "error";
    case Verdict::kCrashed: return "crashed";
    case Verdict::kDiffering: return "differing";
    case Verdict::kInconclusive: return "inconclusive";
    case Verdict::kVerified: return "verified";
    case Verdict::kIdentical: return "identical";
    case Verdict::kRendered: return "rendered";
  }
  return "?";
}

Verdict VerdictOf(verify::Judgement judgement) {
  switch (judgement) {
    case verify::Judgement::kPassed: return Verdict::kVerified;
    case verify::Judgement::kInconclusive: return Verdict::kInconclusive;
    case verify::Judgement::kFailed: break;
  }
  return Verdict::kDiffering;
}

int ExitCodeOf(Verdict verdict) {
  switch (verdict) {
    case Verdict::kError: return kExitBadInput;
    case Verdict::kCrashed: return kExitGpuFailed;
    case Verdict::kDiffering: return kExitImagesDiffer;
    case Verdict::kInconclusive: return kExitInconclusive;
    case Verdict::kVerified:
    case Verdict::kIdentical:
    case Verdict::kRendered: return kExitOk;
  }
  return kExitInternalError;
}

bool IsFailure(Verdict verdict) {
  return verdict == Verdict::kError || verdict == Verdict::kCrashed || verdict == Verdict::kDiffering;
}

}  // namespace twinraster::run
