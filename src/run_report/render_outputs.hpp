// A render record as render prints it: the report's lines, or its --json object.
#pragma once

#include "run/run_record.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace twinraster::run_report {

// render --json's "format"; any change to its keys or their meaning gets a new number
// (docs/json-output.md, docs/schemas/).
inline constexpr const char* kRenderJsonFormat = "twinraster.render/5";

// The lines `render` prints for one scene, each ending in "\n"; `verify_asked`: --verify was
// given, so the verification's own line is printed too.
std::string RenderText(const run::RunRecord& record, bool verify_asked);

// The twinraster.render/5 object (docs/json-output.md), for any verdict: an error's too.
nlohmann::ordered_json RenderJson(const run::RunRecord& record);

// One line on why a scene got its verdict: the problem, the verifier's sentence, or the comparison's.
std::string VerdictReason(const run::RunRecord& record);

}  // namespace twinraster::run_report
