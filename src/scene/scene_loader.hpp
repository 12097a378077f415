// Reads a scene file (JSON, the chapter's vocabulary), and the OBJ files it names, into a validated
// Scene; any problem is a SceneError naming the file, the JSON path (or line and column; in an OBJ
// file, the line) and what is wrong.
#pragma once

#include "scene/scene.hpp"
#include "scene/scene_error.hpp"

#include <filesystem>
#include <string>
#include <string_view>

namespace twinraster {

Scene LoadScene(const std::filesystem::path& file);

// `file_name` is only used in error messages and for Scene::name. The paths of OBJ files the
// scene names start from `directory` (LoadScene: the scene file's; empty: the current directory).
Scene ParseScene(std::string_view json_text, const std::string& file_name, const std::filesystem::path& directory = {});

}  // namespace twinraster
