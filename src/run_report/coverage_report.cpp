#include "run_report/coverage_report.hpp"

#include "base/counted.hpp"
#include "run_report/verify_report.hpp"

#include <nlohmann/json.hpp>

#include <sstream>

namespace twinraster::run_report {

namespace {

std::string Colour(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

nlohmann::ordered_json ColourJson(Rgb8 c) { return {c.r, c.g, c.b}; }

nlohmann::ordered_json PositionJson(const std::optional<verify::CoveragePosition>& p) {
  if (!p) return nullptr;
  return {{"x", p->x}, {"y", p->y}, {"colour", ColourJson(p->colour)}};
}

}  // namespace

std::string CoverageInconclusiveReason(const verify::CoverageVerification& c) {
  if (verify::JudgementOf(c) != verify::Judgement::kInconclusive) return "";
  if (c.work.Exceeded()) return OverBudgetReason(c.work);
  // No primitive may reach any pixel: verify's own words for the same case (verify_report.cpp).
  if (c.certainly_covered == 0 && c.uncertain == 0) {
    return "nothing is in view (no triangle may cover any pixel), so an image with nothing covered is both the "
           "right answer and what a broken engine draws";
  }
  if (c.certainly_covered <= c.holes_allowed) return "an image with nothing covered would pass too";
  if (c.certainly_uncovered == 0) return "an image covered everywhere would pass too";
  const std::uint64_t reachable = c.certainly_covered + c.uncertain;
  return std::to_string(int(100.0 * double(c.uncertain) / double(reachable))) +
         " % of the pixels a primitive may cover are uncertain";
}

std::string CoverageText(const verify::CoverageVerification& c) {
  std::ostringstream s;
  const verify::Judgement judgement = verify::JudgementOf(c);
  s << "coverage "
    << (judgement == verify::Judgement::kPassed         ? "passes"
        : judgement == verify::Judgement::kInconclusive ? "is inconclusive"
                                                        : "fails")
    << ": " << c.certainly_covered << " px certainly covered, " << c.certainly_uncovered << " certainly uncovered, "
    << c.uncertain << " uncertain (free); " << c.spills << " px covered where no primitive may reach";
  if (c.first_spill) {
    s << " (first at (" << c.first_spill->x << ", " << c.first_spill->y << "): " << Colour(c.first_spill->colour)
      << ")";
  }
  s << ", " << c.holes << " px of the clear colour " << Colour(c.background)
    << (c.background_given ? " (--background)" : " (the scene's)") << " where a primitive certainly covers";
  if (c.first_hole) s << " (first at (" << c.first_hole->x << ", " << c.first_hole->y << "))";
  if (c.hole_tolerance_percent > 0) {
    s << ", " << Counted(c.holes_allowed, "hole") << " allowed (" << c.hole_tolerance_percent
      << " % of those certainly covered)" << (c.HolesWithin() ? ": within" : ": beyond");
  }
  if (judgement == verify::Judgement::kInconclusive) s << "; " << CoverageInconclusiveReason(c);
  s << " (subpixel bits " << c.rules.subpixel_bits << (c.rules.strict_lines ? ", strict lines)" : ")");
  if (c.holes > 0 && !c.HolesWithin() && c.spills == 0) {
    s << "\n  only holes: a transform error, or shading that produced the clear colour; render with a clear colour "
         "the shading never produces (docs/verify.md), or allow some with --hole-tolerance";
  }
  return s.str();
}

nlohmann::ordered_json CoverageJson(const CoverageReport& r) {
  using Json = nlohmann::ordered_json;
  const verify::CoverageVerification& c = r.judgement.coverage;
  const std::string reason = CoverageInconclusiveReason(c);
  return {{"format", kCoverageJsonFormat},
          {"scene", r.scene},
          {"image", r.image},
          {"wireframe", r.wireframe},
          {"drawn_by", r.drawn_by ? Json(r.drawn_by->device) : Json(nullptr)},
          {"rules_from", RulesFromJson(r.rules)},
          {"alpha", AlphaJson(r.judgement.not_opaque)},
          {"verdict", verify::JudgementName(verify::JudgementOf(c))},
          {"passed", verify::JudgementOf(c) == verify::Judgement::kPassed},
          {"reason", reason.empty() ? Json(nullptr) : Json(reason)},
          {"subpixel_bits", c.rules.subpixel_bits},
          {"strict_lines", c.rules.strict_lines},
          {"width", c.width},
          {"height", c.height},
          {"background", ColourJson(c.background)},
          {"background_from", c.background_given ? "option" : "scene"},
          {"hole_tolerance_percent", c.hole_tolerance_percent},
          {"pixels",
           {{"certainly_covered", c.certainly_covered},
            {"certainly_uncovered", c.certainly_uncovered},
            {"uncertain", c.uncertain},
            {"uncertain_covered", c.uncertain_covered},
            {"image_covered", c.image_covered},
            {"spills", c.spills},
            {"holes", c.holes},
            {"holes_allowed", c.holes_allowed},
            {"violations", c.Violations()}}},
          {"first_spill", PositionJson(c.first_spill)},
          {"first_hole", PositionJson(c.first_hole)},
          {"map", r.map ? Json(*r.map) : Json(nullptr)},
          {"verify_ms", r.judgement.verify_ms}};
}

std::string CoverageReportText(const CoverageReport& r) {
  std::ostringstream s;
  if (r.drawn_by) s << r.image << ": drawn by " << r.drawn_by->device << " (its PNG notes)\n";
  s << AssumedRulesText(r.image, r.rules);
  const verify::CoverageVerification& c = r.judgement.coverage;
  s << r.image << ": " << CoverageText(c) << "\n";
  s << AlphaText(r.image, r.judgement.not_opaque, std::uint64_t{c.width} * c.height);
  if (r.map) {
    s << "map: " << *r.map
      << " (grey: agrees, amber: uncertain, red: covered where nothing may reach, blue: clear colour where a "
         "primitive must cover, cyan: such a pixel within the tolerance)\n";
  }
  return s.str();
}

}  // namespace twinraster::run_report
