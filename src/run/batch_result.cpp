#include "run/batch_result.hpp"

#include "base/exit_code.hpp"

#include <utility>

namespace twinraster::run {

// counts_ has a slot for each verdict: a verdict added to the enum needs kVerdictCount raised.
static_assert(static_cast<std::size_t>(Verdict::kRendered) + 1 == kVerdictCount);

int Severity(Verdict verdict) {
  switch (verdict) {
    case Verdict::kIdentical: return 0;
    case Verdict::kVerified: return 1;
    case Verdict::kRendered: return 2;
    case Verdict::kInconclusive: return 3;
    case Verdict::kDiffering: return 4;
    case Verdict::kError: return 5;
    case Verdict::kCrashed: return 6;
  }
  return 7;  // not a verdict: worse than any
}

Verdict Worse(Verdict a, Verdict b) { return Severity(a) >= Severity(b) ? a : b; }

void BatchResult::Add(RunRecord record) {
  ++counts_[static_cast<std::size_t>(record.verdict)];
  worst_ = worst_ ? Worse(*worst_, record.verdict) : record.verdict;
  records_.push_back(std::move(record));
}

int BatchResult::ExitCode() const { return worst_ ? ExitCodeOf(*worst_) : kExitOk; }

}  // namespace twinraster::run
