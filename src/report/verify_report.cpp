#include "report/verify_report.hpp"

#include <sstream>

namespace twinraster {

namespace {

nlohmann::ordered_json ColourJson(Rgb8 c) { return {c.r, c.g, c.b}; }

nlohmann::ordered_json ViolationJson(const std::optional<verify::Violation>& v) {
  using Json = nlohmann::ordered_json;
  if (!v) return nullptr;
  Json allowed = Json::array();
  for (const verify::ColourRange& r : v->allowed) allowed.push_back({{"lo", ColourJson(r.lo)}, {"hi", ColourJson(r.hi)}});
  return {{"x", v->x}, {"y", v->y}, {"colour", ColourJson(v->colour)}, {"distance", v->distance}, {"allowed", allowed}};
}

}  // namespace

nlohmann::ordered_json VerificationJson(const verify::Verification& v, const std::optional<std::string>& map,
                                        double verify_ms) {
  using Json = nlohmann::ordered_json;
  return {{"verdict", verify::JudgementName(v.Verdict())},
          {"passed", v.Verdict() == verify::Judgement::kPassed},
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

std::string DifferenceVerdict(std::uint64_t differing_pixels, const verify::Verification& v) {
  std::ostringstream s;
  if (v.NoViolations()) {
    s << "the images differ in " << differing_pixels << " px, all within what Vulkan allows (" << v.uncertain
      << " px uncertain, subpixel bits " << v.options.subpixel_bits << ")";
    if (v.Verdict() == verify::Judgement::kInconclusive) {
      s << ", but the judgement is inconclusive: " << verify::InconclusiveReason(v);
    }
  } else {
    s << v.violations << " px " << (v.violations == 1 ? "is" : "are") << " not allowed: first at (" << v.first->x << ", "
      << v.first->y << "), worst at (" << v.worst->x << ", " << v.worst->y << ") "
      << verify::RangeText(verify::ColourRange::Exactly(v.worst->colour)) << " where ";
    for (std::size_t i = 0; i < v.worst->allowed.size(); ++i) {
      s << (i ? " or " : "") << verify::RangeText(v.worst->allowed[i]);
    }
    s << " may show";
  }
  return s.str();
}

}  // namespace twinraster
