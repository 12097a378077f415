// An OBJ file on its own as a scene (`twinraster render mesh.obj`, as tinyrenderer's command line
// draws a model): the mesh framed by a lookat camera, lit by a headlight; and the one entry point
// for a command's input, a scene file, an OBJ file or a glTF file.
#pragma once

#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

#include <filesystem>
#include <string>

namespace twinraster {

// One instance of the mesh, seen as tinyrenderer sees it: from the direction (1, 1, 3) of the
// OBJ's own right-handed frame, around the centre of the bounding box of the vertices its faces
// use, from far enough that the bounding sphere fills 80 % of the 800x800 canvas; the depth range
// hugs the sphere. The chapter's world is left-handed, so the instance is mirrored in z (scale
// [1, 1, -1]): without that the picture would be tinyrenderer's mirrored. Lighting: ambient 0.1 and
// a directional headlight of intensity 0.9 shining from the camera's direction; Gouraud shading
// when a face names normals (vn), flat otherwise. Scene::name is the file's stem.
Scene SceneForObj(const std::filesystem::path& file);

// SceneForObj for a path ending in .obj (in any case), SceneForGltf for .gltf and .glb, LoadScene
// for any other; then the canvas size chosen, for any of them. A camera or scene chosen for a
// file that is not glTF is a SceneError: such a file has none to choose from.
Scene LoadSceneOrObj(const std::filesystem::path& file, const SceneChoice& choice = {});

// The choice applied to a scene read from elsewhere (a JSON scene on standard input).
void ApplyChoice(Scene& scene, const std::string& file, const SceneChoice& choice);

}  // namespace twinraster
