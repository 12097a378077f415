#include "cli/commands.hpp"
#include "run/verdict.hpp"

namespace twinraster {

int ExitCodeOf(run::Verdict verdict) {
  switch (verdict) {
    case run::Verdict::kError: return kExitBadInput;
    case run::Verdict::kCrashed: return kExitGpuFailed;
    case run::Verdict::kDiffering: return kExitImagesDiffer;
    case run::Verdict::kInconclusive: return kExitInconclusive;
    case run::Verdict::kVerified:
    case run::Verdict::kIdentical:
    case run::Verdict::kRendered: return kExitOk;
  }
  return kExitInternalError;
}

int WorseExit(int a, int b) {
  // Inconclusive (6) is milder than every problem (1 to 5) and worse only than success (0).
  const auto rank = [](int code) { return code == kExitInconclusive ? 1 : code == kExitOk ? 0 : code + 1; };
  return rank(a) >= rank(b) ? a : b;
}

}  // namespace twinraster
