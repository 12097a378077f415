// `explain SCENE --html FILE`: the scene's chain drawn, a panel per space, as the chapter's
// figures draw them: the model in model space; the world from above and from the side with the
// instances, the camera and its frustum; camera space; clip space and NDC; the canvas with the
// final pixel. Each panel shows its matrix by the chapter's name and the traced vertex there; a
// lit scene also shows the normal, N and the lights. Every number comes from `explain --json`'s
// object; the scene gives only which vertices its triangles join.
#pragma once

#include "scene/scene.hpp"

#include <nlohmann/json_fwd.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace twinraster::report {

struct ChainPageOptions {
  std::size_t instance = 0;             // the traced instance: an index into `explain`'s instances
  std::optional<std::size_t> vertex;    // its traced vertex (default: the first inside the clip volume)
};

// `explain` is ExplainJson(scene, ...) with every vertex of the instances it shows.
std::string ChainPageHtml(const Scene& scene, const nlohmann::ordered_json& explain, const ChainPageOptions& options);

}  // namespace twinraster::report
