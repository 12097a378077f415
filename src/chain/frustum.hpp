// The view frustum the camera sees, as the chapter's figures draw it: the camera's position, and
// the corners of the near plane, the viewport (at distance d) and the far plane, in camera space
// and, through M_Camera's inverse, in the world.
#pragma once

#include "chain/matrices.hpp"
#include "scene/scene.hpp"

#include <glm/vec3.hpp>

#include <array>

namespace twinraster {

struct Frustum {
  glm::dvec3 eye{0.0};  // the camera's position (its origin, in camera space)
  // Corners in the order (-x, -y), (+x, -y), (+x, +y), (-x, +y) of camera space.
  std::array<glm::dvec3, 4> near{}, viewport{}, far{};
};

// Where the far plane is drawn: at depth.far, or for an infinite far plane (a glTF camera without
// zfar) at 10 times the larger of near and d, which the drawings can hold.
double DrawnFar(const Scene& scene);

// In camera space: perspective planes widen with z as the viewport does at d; orthographic ones
// are the viewport's size at every z (its plane is drawn at d all the same).
Frustum CameraSpaceFrustum(const Scene& scene);
// The same corners in world space: M_Camera⁻¹ applied to each.
Frustum WorldFrustum(const Scene& scene, const Chain& chain);

}  // namespace twinraster
