// `twinraster explain --json`: a typed Explanation as one JSON object, format twinraster.explain/3
// (docs/json-output.md, docs/schemas/explain.schema.json). It formats only:
// chain/explanation.hpp computes every number.
#pragma once

#include "chain/explanation.hpp"

#include <nlohmann/json_fwd.hpp>

namespace twinraster::explain_report {

// The object's "format": any change to its keys or their meaning gets a new number.
inline constexpr const char* kExplainJsonFormat = "twinraster.explain/3";

// The vertices the object traces: read by tools rather than people, it traces every vertex unless
// one is asked for (explain --json, and the moving page's explainJson()).
inline ExplainVertices JsonVertices(bool vertex_asked) {
  return vertex_asked ? ExplainVertices::kTraced : ExplainVertices::kAll;
}

// Every number as computed, a negative zero included, so that tools read exactly the chain's doubles.
nlohmann::ordered_json ExplainJson(const Explanation& explanation);

// The vertex an instance's trace follows (vertices[traced]), as ExplainJson's "vertices" holds it,
// beside the instance's "index": {"instance": I, "vertex": {...}}, "vertex" null for a model
// without vertices. The moving page's trace line reads this, not the whole object.
nlohmann::ordered_json FollowedVertexJson(const InstanceExplanation& instance);

}  // namespace twinraster::explain_report
