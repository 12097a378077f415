// `twinraster explain`: the chapter's whole chain for a scene, every matrix by the chapter's name
// and every chosen vertex traced object -> world -> camera -> clip -> NDC -> canvas -> framebuffer.
#pragma once

#include "scene/scene.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace twinraster {

// Without --instance, this many instances are traced (the first ones); the rest are counted.
inline constexpr std::size_t kExplainedInstances = 16;

struct ExplainOptions {
  std::optional<std::size_t> instance;  // only this instance
  std::optional<std::size_t> vertex;    // only this vertex of each instance shown
};

// ExplainJson's "format": any change to its keys or their meaning gets a new number
// (docs/json-output.md, docs/schemas/explain.schema.json).
inline constexpr const char* kExplainJsonFormat = "twinraster.explain/3";

// Throws UsageError when the instance or vertex index does not exist, as the two below do.
void CheckExplainOptions(const Scene& scene, const ExplainOptions& options);

// Both throw UsageError when the instance or vertex index does not exist.
std::string ExplainText(const Scene& scene, const ExplainOptions& options);
nlohmann::ordered_json ExplainJson(const Scene& scene, const ExplainOptions& options);

}  // namespace twinraster
