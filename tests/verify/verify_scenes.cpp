#include "verify_scenes.hpp"

#include "../twin/random_scene.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"
#include "support/test_support.hpp"

#include <filesystem>
#include <stdexcept>
#include <string>

namespace twinraster::test {

std::vector<std::filesystem::path> ShippedScenesAndMeshes() {
  std::vector<std::filesystem::path> files = ShippedScenes();
  const std::size_t scenes = files.size();
  for (const auto& entry : std::filesystem::directory_iterator(SourcePath("scenes/meshes"))) {
    if (entry.path().extension() == ".obj") files.push_back(entry.path());
  }
  // The five meshes scripts/make-meshes.py writes, never a folder that came up empty.
  if (files.size() - scenes != 5) throw std::logic_error("expected the 5 OBJ meshes in scenes/meshes");
  return files;
}

Drawn ShippedScene(const std::filesystem::path& file, bool wireframe) {
  Scene scene = LoadSceneOrObj(file);
  scene.wireframe = wireframe;
  DrawList list = BuildDrawList(scene);
  return {std::move(scene), std::move(list)};
}

Drawn RandomScene(std::uint32_t seed, bool wireframe) {
  nlohmann::ordered_json json = RandomSceneJson(seed);
  json["wireframe"] = wireframe;
  Scene scene = ParseScene(json.dump(), "random-" + std::to_string(seed) + ".json");
  DrawList list = BuildDrawList(scene);
  return {std::move(scene), std::move(list)};
}

}  // namespace twinraster::test
