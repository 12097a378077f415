// How a verification reads, for `verify` and for `render`: its sentence, its JSON
// (twinraster.verify/3), and the line render prints about a GPU image that differs from the
// twin's. It judges nothing (verify/ and run/ do).
#pragma once

#include "run/device_rules.hpp"
#include "run/judge_image.hpp"
#include "verify/drawn_by.hpp"
#include "verify/verification.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstdint>
#include <optional>
#include <string>

namespace twinraster::run_report {

inline constexpr const char* kVerifyJsonFormat = "twinraster.verify/3";

// "passes: 21503 px certain, 97 uncertain (0.45 % of the 21600 covered), 0 violations",
// "inconclusive: ..." or "fails: 12 violations, worst at (x, y): ..."
std::string VerificationText(const verify::Verification& v);
// Why a judgement is inconclusive: "an empty image would pass too", or "62 % of the covered pixels
// are uncertain (shared edges apart)"; empty when it is not.
std::string InconclusiveReason(const verify::Verification& v);
// "too much overdraw to judge within the budget: at least N pixel tests, budget M" (the estimate
// stops counting past the budget): the reason for a judgement over budget, in verify's words and
// verify --coverage's.
std::string OverBudgetReason(const verify::WorkBudget& work);
// "(12, 40..42, 200)"
std::string RangeText(const verify::ColourRange& range);

// The judgement and counts, without file names: render nests it, verify adds its files around it.
nlohmann::ordered_json VerificationJson(const verify::Verification& v, const std::optional<std::string>& map,
                                        double verify_ms);

// What a difference between the two images comes to, in one sentence (render prints it after
// "verdict:" and gives it as the verdict's reason): "the images differ in 37 px, all within what
// Vulkan allows (...)" or "12 px are not allowed: first at (x, y) ..."
std::string DifferenceText(std::uint64_t differing_pixels, const verify::Verification& v);

// What `verify` states beside every verdict, with and without --coverage: the rules assumed for want
// of the image's notes, and that alpha is not judged.
// "IMAGE: its PNG notes do not say how the device rasterizes, ... assumed: subpixel bits 4 (give the
// device's with --subpixel-bits N), ..."; empty when nothing was assumed.
std::string AssumedRulesText(const std::string& image, const run::DeviceRules& rules);
// "IMAGE: alpha is not judged: 360000 of 360000 px are not opaque"
std::string AlphaText(const std::string& image, std::uint64_t not_opaque, std::uint64_t pixels);
// {"subpixel_bits": "notes", "strict_lines": "assumed"}: where each rule came from.
nlohmann::ordered_json RulesFromJson(const run::DeviceRules& rules);
// {"judged": false, "not_opaque": 360000}
nlohmann::ordered_json AlphaJson(std::uint64_t not_opaque);

// `verify`'s own outputs: the files it was given and wrote around the judgement.
struct VerifyReport {
  std::string scene, image;  // the arguments, as given
  bool wireframe = false;
  std::optional<verify::DrawnBy> drawn_by;  // what the image's notes say
  run::DeviceRules rules;                   // the rules judged by, and where each came from
  const run::ImageJudgement& judgement;
  std::optional<std::string> map;  // the map's file, when one was written
};
nlohmann::ordered_json VerifyJson(const VerifyReport& report);
std::string VerifyText(const VerifyReport& report);

}  // namespace twinraster::run_report
