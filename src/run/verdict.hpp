// The one verdict of a scene's run, as deqp-runner's status enum is for a test: what the exit
// code, the batch page's colour and the JUnit element all read. Deciding it is run_record.hpp's
// VerdictOf; saying why is run_report/'s.
#pragma once

#include "verify/verification.hpp"

#include <cstddef>

namespace twinraster::run {

// In the batch page's order: failures first.
enum class Verdict {
  kError,         // bad input, or an output that could not be written
  kCrashed,       // the Vulkan driver crashed or timed out
  kDiffering,     // the images differ where the twin promised they would not, or the verifier found a violation
  kInconclusive,  // the images differ, or one was judged, and the verifier could not tell (neither pass nor fail)
  kVerified,      // the images differ, or one was judged, and the verifier passed it
  kIdentical,     // gpu and cpu agree bit for bit
  kRendered,      // one backend drew, nothing was compared or judged
};
inline constexpr std::size_t kVerdictCount = 7;  // kError to kRendered: a count for each

// The verdict a judgement alone gives: passed is verified, failed is differing.
Verdict VerdictOf(verify::Judgement judgement);

const char* VerdictName(Verdict verdict);  // "error", "crashed", ...
bool IsFailure(Verdict verdict);           // error, crashed, differing
// Neither passed nor failed: JUnit's skipped, exit code 6.
inline bool IsInconclusive(Verdict verdict) { return verdict == Verdict::kInconclusive; }
inline bool IsSuccess(Verdict verdict) { return !IsFailure(verdict) && !IsInconclusive(verdict); }

// The exit code of one scene's verdict (base/exit_code.hpp): an error 2, crashed 5, differing 1,
// inconclusive 6, anything else 0. A batch exits with its worst verdict's (batch_result.hpp).
int ExitCodeOf(Verdict verdict);

}  // namespace twinraster::run
