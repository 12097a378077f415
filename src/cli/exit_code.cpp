#include "cli/commands.hpp"

#include "report/render_record.hpp"

namespace twinraster {

int ExitCodeOf(report::Verdict verdict) {
  switch (verdict) {
    case report::Verdict::kError: return kExitBadInput;
    case report::Verdict::kCrashed: return kExitGpuFailed;
    case report::Verdict::kDiffering: return kExitImagesDiffer;
    case report::Verdict::kInconclusive: return kExitInconclusive;
    case report::Verdict::kVerified:
    case report::Verdict::kIdentical:
    case report::Verdict::kRendered: return kExitOk;
  }
  return kExitInternalError;
}

int WorseExit(int a, int b) {
  // Inconclusive (6) is milder than every problem (1 to 5) and worse only than success (0).
  const auto rank = [](int code) { return code == kExitInconclusive ? 1 : code == kExitOk ? 0 : code + 1; };
  return rank(a) >= rank(b) ? a : b;
}

}  // namespace twinraster
