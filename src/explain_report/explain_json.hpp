// `twinraster explain --json`: a typed Explanation as one JSON object, format twinraster.explain/3
// (docs/json-output.md, docs/schemas/explain.schema.json). It formats only:
// chain/explanation.hpp computes every number.
#pragma once

#include "chain/explanation.hpp"

#include <nlohmann/json_fwd.hpp>

namespace twinraster::explain_report {

// The object's "format": any change to its keys or their meaning gets a new number.
inline constexpr const char* kExplainJsonFormat = "twinraster.explain/3";

// Every number as computed, a negative zero included, so that tools read exactly the chain's doubles.
nlohmann::ordered_json ExplainJson(const Explanation& explanation);

}  // namespace twinraster::explain_report
