// Writes a loaded Scene back out as a twinraster JSON scene file (docs/scene-format.md), so that
// bench --loaders can load the same geometry through the JSON loader as through another: every
// model's vertices and triangles, every instance with its M_Model decomposed into the object form
// (scale, an axis-angle rotation, translation), the camera, canvas, viewport, depth and light. It
// does not write normals (JSON scenes carry none), grids, notes or references to OBJ or glTF files,
// and it cannot write a transform that shears: DecomposeModelMatrix says how far off one would be.
#pragma once

#include "scene/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <string>

namespace twinraster::bench {

// How vertex coordinates are written. kExact: the shortest decimal that reads back as the same
// double, so the JSON loader's Scene holds the very same numbers (up to 17 digits). kFloat: the
// shortest decimal that reads back as the same float (up to 9 digits), what an exporter writing a
// glTF file's float32 positions writes; read as double it may differ from the float in its last
// bits. Transforms, the camera and the light are always written exactly.
enum class JsonDigits { kExact, kFloat };

// An affine M_Model as the object form M = T · R · S. `residual` is the largest entry of
// |T · R · S - M| for the rotation as the JSON loader will rebuild it from `axis` and `degrees`
// (chapter convention, rotation.hpp): 0 up to rounding unless M shears.
struct ObjectTransform {
  glm::dvec3 scale{1, 1, 1};  // a mirror (det < 0) is a negative z scale
  glm::dvec3 axis{0, 1, 0};
  double degrees = 0;
  glm::dvec3 translation{0, 0, 0};
  double residual = 0;
};
ObjectTransform DecomposeModelMatrix(const glm::dmat4& m);

// The rotation `r` (orthonormal, det +1) as an axis and an angle in the chapter's convention.
void RotationAxisAngle(const glm::dmat3& r, glm::dvec3& axis, double& degrees);

// The scene as JSON text. Models are named "m0", "m1", ... in Scene::models' order, so that an
// instance names its model as the Scene does; a model is given a "shading" when the scene is lit.
std::string SceneAsJson(const Scene& scene, JsonDigits digits);

}  // namespace twinraster::bench
