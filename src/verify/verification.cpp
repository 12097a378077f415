#include "verify/verification.hpp"

#include <sstream>

namespace twinraster::verify {

namespace {

std::string Colour(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

}  // namespace

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

std::string InconclusiveReason(const Verification& v) {
  if (v.Verdict() != Judgement::kInconclusive) return "";
  if (v.background_excluded == 0) return "an empty image would pass too";
  const double share = v.covered ? 100.0 * double(v.UncertainOther()) / double(v.covered) : 0.0;
  return std::to_string(int(share)) + " % of the covered pixels are uncertain (shared edges apart)";
}

std::string RangeText(const ColourRange& r) {
  if (r.lo == r.hi) return Colour(r.lo);
  const auto channel = [](int lo, int hi) { return lo == hi ? std::to_string(lo) : std::to_string(lo) + ".." + std::to_string(hi); };
  return "(" + channel(r.lo.r, r.hi.r) + ", " + channel(r.lo.g, r.hi.g) + ", " + channel(r.lo.b, r.hi.b) + ")";
}

std::string VerificationText(const Verification& v) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed;
  const double percent = 100.0 * v.UncertainFraction();
  const Judgement verdict = v.Verdict();
  if (verdict != Judgement::kFailed) {
    s << (verdict == Judgement::kPassed ? "passes: " : "inconclusive: ") << v.certain << " px certain, " << v.uncertain
      << " uncertain (" << percent << " % of the " << v.covered << " covered";
    if (v.uncertain_shared_edges > 0) s << ", " << v.uncertain_shared_edges << " of them on shared edges";
    s << "), 0 violations";
    if (verdict == Judgement::kInconclusive) s << "; " << InconclusiveReason(v);
  } else {
    s << "fails: " << v.violations << (v.violations == 1 ? " pixel is" : " pixels are") << " not allowed; worst at ("
      << v.worst->x << ", " << v.worst->y << "): " << Colour(v.worst->colour) << ", allowed ";
    for (std::size_t i = 0; i < v.worst->allowed.size(); ++i) s << (i ? " or " : "") << RangeText(v.worst->allowed[i]);
    s << "; " << v.certain << " px certain, " << v.uncertain << " uncertain";
  }
  s << " (subpixel bits " << v.options.subpixel_bits << (v.options.strict_lines ? ", strict lines)" : ")");
  return s.str();
}

}  // namespace twinraster::verify
