#include "cpu/lighting.hpp"

#include <cmath>

namespace twinraster::cpu {
namespace {

float Dot(const glm::vec3& a, const glm::vec3& b) { return (a.x * b.x + a.y * b.y) + a.z * b.z; }

}  // namespace

glm::vec3 LightVertex(const DrawLighting& lighting, const LitInstance& instance, const glm::vec3& position,
                      const glm::vec3& normal, Rgb8 base) {
  const glm::mat4x3& m = instance.model;
  const glm::mat3& nm = instance.normal;
  glm::vec3 world, n;
  for (int r = 0; r < 3; ++r) {
    world[r] = ((m[0][r] * position.x + m[1][r] * position.y) + m[2][r] * position.z) + m[3][r];
    n[r] = (nm[0][r] * normal.x + nm[1][r] * normal.y) + nm[2][r] * normal.z;
  }
  const float n_length = std::sqrt(Dot(n, n));
  n = glm::vec3(n.x / n_length, n.y / n_length, n.z / n_length);
  float intensity = lighting.ambient;
  for (const DrawLight& light : lighting.lights) {
    const glm::vec3 l = light.point
                            ? glm::vec3(light.vector.x - world.x, light.vector.y - world.y, light.vector.z - world.z)
                            : light.vector;
    const float n_dot_l = Dot(n, l);
    if (n_dot_l > 0.0f) {
      const float l_length = std::sqrt(Dot(l, l));
      intensity = intensity + light.intensity * (n_dot_l / l_length);
    }
  }
  // GLSL's min(I, 1.0): I when I < 1 (a NaN I stays NaN; see UnormByte).
  const float scale = intensity < 1.0f ? intensity : 1.0f;
  const glm::vec3 k = BaseColour(base);
  return glm::vec3(k.x * scale, k.y * scale, k.z * scale);
}

}  // namespace twinraster::cpu
