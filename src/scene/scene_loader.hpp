// Reads a scene file (JSON, the chapter's vocabulary) into a validated Scene; any problem is a
// SceneError naming the file, the JSON path (or line and column) and what is wrong.
#pragma once

#include "scene/scene.hpp"
#include "scene/scene_error.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace twinraster {

Scene LoadScene(const std::filesystem::path& file);

// `file_name` is only used in error messages and for Scene::name.
Scene ParseScene(std::string_view json_text, const std::string& file_name);

}  // namespace twinraster
