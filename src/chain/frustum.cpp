#include "chain/frustum.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include <algorithm>
#include <cmath>

namespace twinraster {

namespace {

std::array<glm::dvec3, 4> Corners(const Scene& scene, double z) {
  const bool perspective = scene.viewport.projection == Projection::kPerspective;
  const double grow = perspective ? z / scene.viewport.distance : 1.0;
  const double hx = scene.viewport.width / 2 * grow, hy = scene.viewport.height / 2 * grow;
  return {glm::dvec3{-hx, -hy, z}, glm::dvec3{hx, -hy, z}, glm::dvec3{hx, hy, z}, glm::dvec3{-hx, hy, z}};
}

}  // namespace

double DrawnFar(const Scene& scene) {
  return std::isinf(scene.depth.far) ? 10 * std::max(scene.depth.near, scene.viewport.distance) : scene.depth.far;
}

Frustum CameraSpaceFrustum(const Scene& scene) {
  Frustum f;
  f.near = Corners(scene, scene.depth.near);
  f.viewport = Corners(scene, scene.viewport.distance);
  f.far = Corners(scene, DrawnFar(scene));
  return f;
}

Frustum WorldFrustum(const Scene& scene, const Chain& chain) {
  const glm::dmat4 to_world = glm::inverse(chain.camera);
  const auto world = [&](const glm::dvec3& p) { return glm::dvec3(to_world * glm::dvec4(p, 1.0)); };
  Frustum f = CameraSpaceFrustum(scene);
  f.eye = world(f.eye);
  for (auto* plane : {&f.near, &f.viewport, &f.far}) {
    for (glm::dvec3& corner : *plane) corner = world(corner);
  }
  return f;
}

}  // namespace twinraster
