// A render record as render prints it: the report's lines, or its --json object.
#pragma once

#include "report/render_record.hpp"

#include <nlohmann/json_fwd.hpp>

#include <string>

namespace twinraster::report {

// The lines `render` prints for one scene, each ending in "\n"; `verify_asked`: --verify was
// given, so the verification's own line is printed too.
std::string RenderText(const RenderRecord& record, bool verify_asked);

// The twinraster.render/4 object (docs/json-output.md).
nlohmann::ordered_json RenderJson(const RenderRecord& record);

}  // namespace twinraster::report
