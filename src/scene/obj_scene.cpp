#include "scene/obj_scene.hpp"

#include "scene/obj_file.hpp"
#include "scene/rotation.hpp"
#include "scene/scene_loader.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <limits>
#include <string>

namespace twinraster {

namespace {

// The bounding sphere's share of the viewport's half-width (and height): 80 %, a margin of 10 %
// of the canvas on every side.
constexpr double kFill = 0.8;
// Near and far sit this much beyond the sphere, so that no vertex lies on a clipping plane.
constexpr double kDepthMargin = 1.1;

struct Sphere {
  glm::dvec3 centre{0.0};
  double radius = 0;
};

// Around the centre of the bounding box of the vertices the triangles use (a vertex no face
// names does not move the camera), with the radius that reaches the farthest of them.
Sphere BoundingSphere(const Model& model) {
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  for (const Triangle& t : model.triangles) {
    for (const std::uint32_t v : t.v) {
      low = glm::min(low, model.vertices[v]);
      high = glm::max(high, model.vertices[v]);
    }
  }
  Sphere sphere;
  sphere.centre = (low + high) / 2.0;
  for (const Triangle& t : model.triangles) {
    for (const std::uint32_t v : t.v)
      sphere.radius = std::max(sphere.radius, glm::length(model.vertices[v] - sphere.centre));
  }
  // A mesh that is a single point still needs a camera apart from it: a radius at least a
  // millionth of the centre's distance from the origin (or of 1).
  const double scale = std::max({1.0, std::abs(sphere.centre.x), std::abs(sphere.centre.y), std::abs(sphere.centre.z)});
  sphere.radius = std::max(sphere.radius, 1e-6 * scale);
  return sphere;
}

}  // namespace

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
  const glm::dvec3 mirror(1, 1, -1);
  const Sphere sphere = BoundingSphere(model);
  const glm::dvec3 centre = sphere.centre * mirror;
  const glm::dvec3 toward_eye = glm::dvec3(1, 1, 3) * mirror;
  // The sphere's silhouette, seen from distance D, is a circle of angular radius asin(r / D);
  // its tangent must be kFill times the viewport's half-width over d (0.5 / 1).
  const double tangent = kFill * 0.5;
  const double distance = sphere.radius * std::sqrt(1 + tangent * tangent) / tangent;  // r / sin
  const glm::dvec3 eye = centre + distance * glm::normalize(toward_eye);

  scene.canvas = Canvas{800, 800, Rgb8{40, 40, 48}};
  scene.viewport = Viewport{1, 1, 1, Projection::kPerspective};
  scene.depth.near = distance - kDepthMargin * sphere.radius;
  scene.depth.far = distance + kDepthMargin * sphere.radius;
  scene.camera = CameraLookingAt(eye, centre, glm::dvec3(0, 1, 0));
  scene.models.push_back(std::move(model));
  Instance instance;
  instance.transform.scale = mirror;
  scene.instances.push_back(instance);
  // A headlight: l points from the surface toward the light, here toward the camera.
  scene.lighting = Lighting{0.1, {Light{Light::Kind::kDirectional, toward_eye, 0.9}}};
  return scene;
}

Scene LoadSceneOrObj(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".obj" ? SceneForObj(file) : LoadScene(file);
}

}  // namespace twinraster
