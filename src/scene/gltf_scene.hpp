// A glTF document as the chapter's scene: each node with a mesh an instance whose M_Model is the
// node chain from the root composed in double, then mirrored into the chapter's left-handed world;
// the camera from a camera node (or the asset framed as an OBJ is); each primitive a model with
// its material's base colour. It does not read files (gltf_document.hpp does) and draws no
// texture, skin, morph target, animation, point or line: Scene::notes names what it left out.
#pragma once

#include "scene/gltf_document.hpp"
#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

#include <filesystem>
#include <string>

namespace twinraster {

// The default canvas's longer side when the camera gives an aspect ratio (and both sides
// without one).
inline constexpr std::uint32_t kGltfCanvasSide = 800;

// `choice.camera`: a camera's index in "cameras" or its name (default: the first camera node met
// depth first from the scene's roots); `choice.scene`: an index in "scenes" (default: "scene",
// else 0, else every root node); `choice.size`: the canvas. Throws SceneError naming the file.
Scene GltfScene(const GltfDocument& doc, const SceneChoice& choice, const std::string& name);

// The scene file's "gltf" model: the meshes of the file's default scene, each vertex moved by its
// node chain and mirrored into the chapter's frame, as one model (the file's cameras unused).
// `lit`: the scene has lighting. Throws SceneError naming the file.
Model GltfModel(const GltfDocument& doc, const std::string& name, bool lit);

// ReadGltf, then GltfScene named by the file's stem.
Scene SceneForGltf(const std::filesystem::path& file, const SceneChoice& choice);

// True for a name ending in .gltf or .glb, in any case.
bool IsGltfName(const std::filesystem::path& file);

}  // namespace twinraster
