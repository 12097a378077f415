#include "report/render_record.hpp"

#include "report/verify_report.hpp"

namespace twinraster::report {

const BackendRecord* RenderRecord::Backend(const std::string& backend_name) const {
  for (const BackendRecord& b : backends) {
    if (b.name == backend_name) return &b;
  }
  return nullptr;
}

Verdict VerdictOf(const RenderRecord& r) {
  if (!r.error.empty()) return Verdict::kError;
  for (const BackendRecord& b : r.backends) {
    if (!b.Drawn()) return Verdict::kCrashed;
  }
  if (r.verification && !r.verification->NoViolations()) return Verdict::kDiffering;
  const bool differ = r.comparison && !r.comparison->Equal();
  if (differ && r.TwinPromised()) return Verdict::kDiffering;
  const auto judged = [&] {
    return r.verification->Verdict() == verify::Judgement::kPassed ? Verdict::kVerified : Verdict::kInconclusive;
  };
  if (differ) return r.verification ? judged() : Verdict::kDiffering;
  if (r.comparison) return Verdict::kIdentical;
  return r.verification ? judged() : Verdict::kRendered;
}

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

bool IsFailure(Verdict verdict) {
  return verdict == Verdict::kError || verdict == Verdict::kCrashed || verdict == Verdict::kDiffering;
}

std::string VerdictReason(const RenderRecord& r) {
  switch (VerdictOf(r)) {
    case Verdict::kError:
      return r.error;
    case Verdict::kCrashed:
      for (const BackendRecord& b : r.backends) {
        if (!b.Drawn()) return b.name + " " + b.status + ": " + b.problem;
      }
      return "crashed";
    case Verdict::kDiffering:
    case Verdict::kInconclusive:
    case Verdict::kVerified:
      if (r.comparison && !r.comparison->Equal() && r.verification) {
        return DifferenceVerdict(r.comparison->differing_pixels, *r.verification);
      }
      if (r.verification) return r.judged + " image " + verify::VerificationText(*r.verification);
      return "the images differ in " + std::to_string(r.comparison->differing_pixels) + " px";
    case Verdict::kIdentical:
      return "0 differing pixels";
    case Verdict::kRendered:
      return "drawn";
  }
  return "";
}

}  // namespace twinraster::report
