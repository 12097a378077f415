// How `verify --coverage` reads: its sentence and its JSON (twinraster.verify-coverage/2, the
// second form of docs/schemas/verify.schema.json). It judges nothing (verify/ and run/ do).
#pragma once

#include "run/device_rules.hpp"
#include "run/judge_coverage.hpp"
#include "verify/drawn_by.hpp"

#include <nlohmann/json_fwd.hpp>

#include <optional>
#include <string>

namespace twinraster::run_report {

inline constexpr const char* kCoverageJsonFormat = "twinraster.verify-coverage/2";

// "coverage passes: 98472 px certainly covered, 261276 certainly uncovered, 252 uncertain; 0 px
// covered where no primitive may reach, 0 px of the clear colour (255, 255, 255) where a primitive
// certainly covers (subpixel bits 4)", or "coverage fails: ..." naming the first of each kind.
std::string CoverageText(const verify::CoverageVerification& c);
// Why a coverage judgement is inconclusive; empty when it is not.
std::string CoverageInconclusiveReason(const verify::CoverageVerification& c);

struct CoverageReport {
  std::string scene, image;  // the arguments, as given
  bool wireframe = false;
  std::optional<verify::DrawnBy> drawn_by;  // what the image's notes say
  run::DeviceRules rules;                   // the rules judged by, and where each came from
  const run::CoverageJudgement& judgement;
  std::optional<std::string> map;  // the map's file, when one was written
};
nlohmann::ordered_json CoverageJson(const CoverageReport& report);
std::string CoverageReportText(const CoverageReport& report);

}  // namespace twinraster::run_report
