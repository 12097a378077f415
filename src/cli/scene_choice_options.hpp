// The options that choose what of a scene is drawn as it is read, the same in render, explain
// and verify: --camera N|NAME and --scene N (glTF files), --size WxH (any scene). It parses the
// words; scene/scene_choice.hpp says what they do.
#pragma once

#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

#include <optional>
#include <string>

namespace CLI {
class App;
}

namespace twinraster::cli {

struct SceneChoiceArguments {
  std::optional<std::string> camera;
  std::optional<std::size_t> scene;
  std::optional<std::string> size;  // "WxH"
};

void AddSceneChoiceOptions(CLI::App& command, SceneChoiceArguments& a);

// The parsed choice; throws UsageError for a --size that is not WxH with sides in 1..16384.
SceneChoice ChoiceOf(const SceneChoiceArguments& a);

// What the scene's file holds that is not drawn (Scene::notes), one "note:" line each on standard
// error, naming the file.
void PrintSceneNotes(const Scene& scene, const std::string& file);

}  // namespace twinraster::cli
