#include "run_report/verify_report.hpp"

#include <nlohmann/json.hpp>

#include <sstream>

namespace twinraster::run_report {

namespace {

std::string Colour(Rgb8 c) {
  return "(" + std::to_string(c.r) + ", " + std::to_string(c.g) + ", " + std::to_string(c.b) + ")";
}

nlohmann::ordered_json ColourJson(Rgb8 c) { return {c.r, c.g, c.b}; }

nlohmann::ordered_json ViolationJson(const std::optional<verify::Violation>& v) {
  using Json = nlohmann::ordered_json;
  if (!v) return nullptr;
  Json allowed = Json::array();
  for (const verify::ColourRange& r : v->allowed)
    allowed.push_back({{"lo", ColourJson(r.lo)}, {"hi", ColourJson(r.hi)}});
  return {{"x", v->x}, {"y", v->y}, {"colour", ColourJson(v->colour)}, {"distance", v->distance}, {"allowed", allowed}};
}

// What a judgement of an image where no triangle may cover any pixel can say (covered == 0).
constexpr const char* kNothingInView =
    "nothing is in view (no triangle may cover any pixel), so an empty image is both the right answer "
    "and what a broken renderer draws";

}  // namespace

std::string OverBudgetReason(const verify::WorkBudget& work) {
  return "too much overdraw to judge within the budget: at least " + std::to_string(work.pixel_tests) +
         " pixel tests, budget " + std::to_string(work.budget);
}

std::string InconclusiveReason(const verify::Verification& v) {
  if (verify::JudgementOf(v) != verify::Judgement::kInconclusive) return "";
  if (v.work.Exceeded()) return OverBudgetReason(v.work);
  if (v.covered == 0) return kNothingInView;
  if (v.background_excluded == 0) return "an empty image would pass too";
  const double share = v.covered ? 100.0 * double(v.UncertainOther()) / double(v.covered) : 0.0;
  return std::to_string(int(share)) + " % of the covered pixels are uncertain (shared edges apart)";
}

std::string RangeText(const verify::ColourRange& r) {
  if (r.lo == r.hi) return Colour(r.lo);
  const auto channel = [](int lo, int hi) {
    return lo == hi ? std::to_string(lo) : std::to_string(lo) + ".." + std::to_string(hi);
  };
  return "(" + channel(r.lo.r, r.hi.r) + ", " + channel(r.lo.g, r.hi.g) + ", " + channel(r.lo.b, r.hi.b) + ")";
}

std::string VerificationText(const verify::Verification& v) {
  std::ostringstream s;
  s.precision(2);
  s << std::fixed;
  const double percent = 100.0 * v.UncertainFraction();
  const verify::Judgement judgement = verify::JudgementOf(v);
  if (v.work.Exceeded()) {
    s << "inconclusive: " << OverBudgetReason(v.work) << "; no pixel was judged";
  } else if (judgement == verify::Judgement::kInconclusive && v.covered == 0) {
    // No count says more than that: every pixel is the background, certainly.
    s << "inconclusive: " << kNothingInView << "; all " << v.certain << " px are the background, 0 violations";
  } else if (judgement != verify::Judgement::kFailed) {
    s << (judgement == verify::Judgement::kPassed ? "passes: " : "inconclusive: ") << v.certain << " px certain, "
      << v.uncertain << " uncertain (" << percent << " % of the " << v.covered << " covered";
    if (v.uncertain_shared_edges > 0) s << ", " << v.uncertain_shared_edges << " of them on shared edges";
    s << "), 0 violations";
    if (judgement == verify::Judgement::kInconclusive) s << "; " << InconclusiveReason(v);
  } else {
    s << "fails: " << v.violations << (v.violations == 1 ? " pixel is" : " pixels are") << " not allowed; worst at ("
      << v.worst->x << ", " << v.worst->y << "): " << Colour(v.worst->colour) << ", allowed ";
    for (std::size_t i = 0; i < v.worst->allowed.size(); ++i) s << (i ? " or " : "") << RangeText(v.worst->allowed[i]);
    s << "; " << v.certain << " px certain, " << v.uncertain << " uncertain";
  }
  s << " (subpixel bits " << v.options.subpixel_bits << (v.options.strict_lines ? ", strict lines)" : ")");
  return s.str();
}

nlohmann::ordered_json VerificationJson(const verify::Verification& v, const std::optional<std::string>& map,
                                        double verify_ms) {
  using Json = nlohmann::ordered_json;
  return {{"verdict", verify::JudgementName(verify::JudgementOf(v))},
          {"passed", verify::JudgementOf(v) == verify::Judgement::kPassed},
          {"subpixel_bits", v.options.subpixel_bits},
          {"strict_lines", v.options.strict_lines},
          {"width", v.width},
          {"height", v.height},
          {"pixels",
           {{"certain", v.certain},
            {"uncertain", v.uncertain},
            {"uncertain_shared_edges", v.uncertain_shared_edges},
            {"violations", v.violations},
            {"covered", v.covered},
            {"background_excluded", v.background_excluded}}},
          {"uncertain_fraction", v.UncertainFraction()},
          {"worst", ViolationJson(v.worst)},
          {"first", ViolationJson(v.first)},
          {"map", map ? Json(*map) : Json(nullptr)},
          {"verify_ms", verify_ms}};
}

std::string DifferenceText(std::uint64_t differing_pixels, const verify::Verification& v) {
  std::ostringstream s;
  if (v.NoViolations()) {
    s << "the images differ in " << differing_pixels << " px, all within what Vulkan allows (" << v.uncertain
      << " px uncertain, subpixel bits " << v.options.subpixel_bits << ")";
    if (verify::JudgementOf(v) == verify::Judgement::kInconclusive) {
      s << ", but the judgement is inconclusive: " << InconclusiveReason(v);
    }
  } else {
    s << v.violations << " px " << (v.violations == 1 ? "is" : "are") << " not allowed: first at (" << v.first->x
      << ", " << v.first->y << "), worst at (" << v.worst->x << ", " << v.worst->y << ") "
      << RangeText(verify::ColourRange::Exactly(v.worst->colour)) << " where ";
    for (std::size_t i = 0; i < v.worst->allowed.size(); ++i) {
      s << (i ? " or " : "") << RangeText(v.worst->allowed[i]);
    }
    s << " may show";
  }
  return s.str();
}

std::string AssumedRulesText(const std::string& image, const run::DeviceRules& d) {
  if (!d.AnyAssumed()) return "";
  const bool bits = d.subpixel_bits == run::RuleSource::kAssumed, lines = d.strict_lines == run::RuleSource::kAssumed;
  const std::string both = bits && lines ? " and " : "";
  return image +
         ": its PNG notes do not say how the device rasterizes (a tool that re-saved it may have dropped them): "
         "assumed the spec's loosest, " +
         (bits ? "subpixel bits " + std::to_string(d.rules.subpixel_bits) : "") + both +
         (lines ? "non-strict lines" : "") + "; give the device's with " + (bits ? "--subpixel-bits N" : "") + both +
         (lines ? "--strict-lines true|false" : "") + "\n";
}

std::string AlphaText(const std::string& image, std::uint64_t not_opaque, std::uint64_t pixels) {
  return image + ": alpha is not judged: " + std::to_string(not_opaque) + " of " + std::to_string(pixels) +
         " px are not opaque\n";
}

nlohmann::ordered_json RulesFromJson(const run::DeviceRules& d) {
  return {{"subpixel_bits", run::RuleSourceName(d.subpixel_bits)},
          {"strict_lines", run::RuleSourceName(d.strict_lines)}};
}

nlohmann::ordered_json AlphaJson(std::uint64_t not_opaque) { return {{"judged", false}, {"not_opaque", not_opaque}}; }

nlohmann::ordered_json VerifyJson(const VerifyReport& r) {
  nlohmann::ordered_json j;
  j["format"] = kVerifyJsonFormat;
  j["scene"] = r.scene;
  j["image"] = r.image;
  j["wireframe"] = r.wireframe;
  j["drawn_by"] = r.drawn_by ? nlohmann::ordered_json(r.drawn_by->device) : nlohmann::ordered_json(nullptr);
  j["rules_from"] = RulesFromJson(r.rules);
  j["alpha"] = AlphaJson(r.judgement.not_opaque);
  const nlohmann::ordered_json fields = VerificationJson(r.judgement.verification, r.map, r.judgement.verify_ms);
  for (const auto& [key, value] : fields.items()) j[key] = value;
  return j;
}

std::string VerifyText(const VerifyReport& r) {
  std::ostringstream s;
  if (r.drawn_by) s << r.image << ": drawn by " << r.drawn_by->device << " (its PNG notes)\n";
  s << AssumedRulesText(r.image, r.rules);
  const verify::Verification& v = r.judgement.verification;
  s << r.image << ": " << VerificationText(v) << "\n";
  s << AlphaText(r.image, r.judgement.not_opaque, std::uint64_t{v.width} * v.height);
  if (r.map) s << "map: " << *r.map << " (grey: certain, amber: uncertain, red: not allowed)\n";
  return s.str();
}

}  // namespace twinraster::run_report
