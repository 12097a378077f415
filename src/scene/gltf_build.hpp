// Inside gltf_scene: the pieces a glTF document becomes, each from the typed GltfDocument: a
// primitive's model, the instances of the nodes that hold meshes, and the scene's camera. Not for
// other stages: they take GltfScene or GltfModel.
#pragma once

#include "scene/gltf_document.hpp"
#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

#include <glm/mat4x4.hpp>

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::gltf {

// One primitive's model: its triangles in the spec's vertex order (strips and fans as Vulkan
// assembles them, so the first corner is the provoking vertex), every index checked against the
// vertices, the material's base colour in sRGB bytes, its normals. Empty for a primitive that
// draws no triangle (points, lines, fewer than three vertices): `notes` says so.
std::optional<Model> PrimitiveModel(const GltfDocument& doc, std::size_t mesh, std::size_t primitive,
                                    std::vector<std::string>& notes);

// A node met walking a scene from its roots, depth first in the file's order.
struct PlacedNode {
  std::size_t node = 0;
  glm::dmat4 world{1.0};  // root · ... · node, in glTF's right-handed frame
};

// The nodes of the scene, or of every root when `scene` is empty, in walk order.
std::vector<PlacedNode> WalkScene(const GltfDocument& doc, const std::optional<std::size_t>& scene);

// The steps of M_Model for an instance of `node`: its local matrix, its parent's, ... up to the
// root's, then the chapter's mirror; shared by the instances of its primitives.
std::shared_ptr<const std::vector<TransformStep>> NodeSteps(const GltfDocument& doc, std::size_t node);

// Sets the scene's camera, viewport, depth, canvas and headlight from the camera node, as
// gltf_scene.hpp describes; `size`, when given, is the canvas.
void PlaceCamera(const GltfDocument& doc, const PlacedNode& at, const std::optional<CanvasSize>& size, Scene& scene);

// The camera node `choice` names (an index in "cameras" or a name), else the first one walked;
// empty when the walk meets none and none was asked for. Throws SceneError for a choice that
// names no camera, or one no node of the scene places.
std::optional<PlacedNode> ChooseCamera(const GltfDocument& doc, const std::vector<PlacedNode>& walk,
                                       const std::optional<std::string>& choice);

}  // namespace twinraster::gltf
