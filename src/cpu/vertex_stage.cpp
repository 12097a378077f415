#include "cpu/vertex_stage.hpp"

namespace twinraster::cpu {

glm::vec4 VertexStage(const glm::mat4& f, const glm::vec3& p) {
  glm::vec4 clip(0.0f);
  for (int r = 0; r < 4; ++r) {
    // No "w * F[3]": the position's w is 1, and the shader adds column 3 as it is.
    clip[r] = ((f[0][r] * p.x + f[1][r] * p.y) + f[2][r] * p.z) + f[3][r];
  }
  return clip;
}

}  // namespace twinraster::cpu
