#include "scene/rotation.hpp"

#include "base/trigonometry.hpp"

#include <glm/geometric.hpp>

namespace twinraster {

namespace {

glm::dmat3 RotationBy(glm::dvec3 axis, SineCosine angle) {
  // R = cos θ · I - sin θ · [a]× + (1 - cos θ) · a aᵀ, the transpose of Rodrigues' formula;
  // about Y this is exactly the chapter demo's matrix.
  const double c = angle.cosine, s = angle.sine, k = 1.0 - c;
  const double x = axis.x, y = axis.y, z = axis.z;
  const double rows[3][3] = {
      {c + k * x * x, k * x * y + s * z, k * x * z - s * y},
      {k * y * x - s * z, c + k * y * y, k * y * z + s * x},
      {k * z * x + s * y, k * z * y - s * x, c + k * z * z},
  };
  glm::dmat3 m(0.0);
  for (int r = 0; r < 3; ++r)
    for (int col = 0; col < 3; ++col) m[col][r] = rows[r][col];
  return m;
}

}  // namespace

// In degrees, by the project's own sine and cosine: 90° gives exact 0 and 1, and every build
// (glibc's, or the browser's musl) the same bits.
glm::dmat3 Rotation(glm::dvec3 axis, double degrees) { return RotationBy(axis, SineCosineOfDegrees(degrees)); }

glm::dmat3 BookRotation(glm::dvec3 axis, double degrees) {
  return RotationBy(axis, SineCosineOfRoundedRadians(degrees));
}

glm::dmat3 AccumulatedRotation(glm::dvec3 axis, double degrees, int steps, bool reorthonormalize) {
  const glm::dmat3 step = Rotation(axis, degrees / steps);
  glm::dmat3 r(1.0);
  for (int i = 0; i < steps; ++i) {
    r = step * r;
    if (reorthonormalize) {
      const glm::dvec3 x = glm::normalize(r[0]);
      const glm::dvec3 y = glm::normalize(r[1] - glm::dot(r[1], x) * x);
      r = glm::dmat3(x, y, glm::cross(x, y));
    }
  }
  return r;
}

Camera CameraLookingAt(glm::dvec3 eye, glm::dvec3 center, glm::dvec3 up) {
  // Camera axes in world space. In a left-handed frame with +Y up and +Z forward, +X = Y × Z.
  const glm::dvec3 forward = glm::normalize(center - eye);
  const glm::dvec3 right = glm::normalize(glm::cross(up, forward));
  const glm::dvec3 true_up = glm::cross(forward, right);
  // C_R maps camera axes to world axes, so its columns are those axes.
  return Camera{eye, glm::dmat3(right, true_up, forward)};
}

}  // namespace twinraster
