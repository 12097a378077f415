#include "run/run_record.hpp"

#include <filesystem>

namespace twinraster::run {

const char* BackendName(Backend backend) { return backend == Backend::kGpu ? "gpu" : "cpu"; }

const char* StatusName(BackendStatus status) {
  switch (status) {
    case BackendStatus::kRendered: return "rendered";
    case BackendStatus::kCrashed: return "crashed";
    case BackendStatus::kTimedOut: return "timed out";
  }
  return "?";
}

const char* RulesName(Rules rules) { return rules == Rules::kBook ? "book" : "vulkan"; }

const BackendRecord* RunRecord::Find(Backend wanted) const {
  for (const BackendRecord& b : backends) {
    if (b.backend == wanted) return &b;
  }
  return nullptr;
}

BackendRecord* RunRecord::Find(Backend wanted) {
  return const_cast<BackendRecord*>(static_cast<const RunRecord&>(*this).Find(wanted));
}

Verdict VerdictOf(const RunRecord& r) {
  if (!r.error.empty()) return Verdict::kError;
  for (const BackendRecord& b : r.backends) {
    if (!b.Drawn()) return Verdict::kCrashed;
  }
  if (r.verification && !r.verification->NoViolations()) return Verdict::kDiffering;
  if (r.Differ() && r.TwinPromised()) return Verdict::kDiffering;
  // With no violation left, a judgement is verified or inconclusive.
  if (r.Differ()) return r.verification ? VerdictOf(verify::JudgementOf(*r.verification)) : Verdict::kDiffering;
  if (r.comparison) return Verdict::kIdentical;
  return r.verification ? VerdictOf(verify::JudgementOf(*r.verification)) : Verdict::kRendered;
}

RunRecord ErrorRecord(const std::string& scene, const std::string& message) {
  RunRecord r;
  r.scene = scene;
  r.name = std::filesystem::path(scene).stem().string();
  r.error = message;
  r.verdict = Verdict::kError;
  return r;
}

}  // namespace twinraster::run
