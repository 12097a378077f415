#include "scene/obj_scene.hpp"

#include "scene/framing.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/obj_file.hpp"
#include "scene/rotation.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace twinraster {

Scene SceneForObj(const std::filesystem::path& file) {
  Scene scene;
  scene.name = file.stem().string();
  Model model = ObjModel(ReadObjFile(file), scene.name, kDefaultObjColour);
  model.source = file.string();
  const bool has_normals = !model.triangle_normals.empty();
  model.shading = has_normals ? Shading::kGouraud : Shading::kFlat;

  // OBJ files are right-handed (+Y up, +Z toward the viewer); the chapter's world is left-handed.
  // Mirroring z turns the one into the other, so the camera, placed in the mirrored world, sees
  // what tinyrenderer's sees from (1, 1, 3). The lit normals follow by the inverse transpose.
  // A vertex no face names does not move the camera.
  const Sphere sphere = BoundingSphere([&model](const auto& point) {
    for (const Triangle& t : model.triangles) {
      for (const std::uint32_t v : t.v) point(model.vertices[v]);
    }
  });
  FrameAsset(sphere, scene);
  scene.models.push_back(std::move(model));
  Instance instance;
  instance.transform.scale = kMirror;
  scene.instances.push_back(instance);
  return scene;
}

void ApplyChoice(Scene& scene, const std::string& file, const SceneChoice& choice) {
  if (choice.camera)
    throw SceneError(file, "(file)", "--camera " + *choice.camera + ": only a glTF file has cameras to choose");
  if (choice.scene) throw SceneError(file, "(file)", "--scene: only a glTF file has scenes to choose");
  if (choice.size) ResizeCanvas(scene, *choice.size);
}

Scene LoadSceneOrObj(const std::filesystem::path& file, const SceneChoice& choice) {
  if (IsGltfName(file)) return SceneForGltf(file, choice);
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  Scene scene = extension == ".obj" ? SceneForObj(file) : LoadScene(file);
  ApplyChoice(scene, file.string(), choice);
  return scene;
}

}  // namespace twinraster
