// Stage 1: the vertex stage sums F · (p, 1) in the shader's order.
#include "cpu/vertex_stage.hpp"

#include "support/catch.hpp"

using twinraster::cpu::VertexStage;

TEST_CASE("vertex stage sums ((F0*x + F1*y) + F2*z) + F3 in float", "[cpu][vertex]") {
  // Row 0 of F is (1, 1, 1, 0.25). With p = (1e8, 1, -1e8):
  //   ((1e8 + 1) + -1e8) + 0.25: 1e8 + 1 rounds to 1e8 (float spacing there is 8), so x = 0.25;
  //   summing x and z first would give (0 + 1) + 0.25 = 1.25 instead.
  glm::mat4 f(1.0f);
  f[1][0] = 1.0f;   // column 1, row 0
  f[2][0] = 1.0f;   // column 2, row 0
  f[3][0] = 0.25f;  // column 3 (translation), row 0
  const glm::vec3 p(1e8f, 1.0f, -1e8f);
  const glm::vec4 clip = VertexStage(f, p);
  CHECK(clip.x == 0.25f);
  CHECK(clip.y == 1.0f);   // row 1 is (0, 1, 0, 0)
  CHECK(clip.z == -1e8f);  // row 2 is (0, 0, 1, 0)
  CHECK(clip.w == 1.0f);   // row 3 is (0, 0, 0, 1): column 3 is added, not multiplied by anything

  // The other association really does give something else, so the check above means something.
  volatile float x = p.x, y = p.y, z = p.z;
  CHECK((x + z) + y + 0.25f == 1.25f);
}

TEST_CASE("vertex stage rounds every product before adding (no fused multiply-add)", "[cpu][vertex]") {
  // x * a with a = 1 + 2^-12 and x = 1 + 2^-12: exact product 1 + 2^-11 + 2^-24, which rounds to
  // the even neighbour 1 + 2^-11; adding -(1 + 2^-11) then gives exactly 0. A fused multiply-add
  // would keep the 2^-24.
  glm::mat4 f(0.0f);
  f[0][0] = 1.0f + 0x1p-12f;
  f[3][0] = -(1.0f + 0x1p-11f);
  const glm::vec4 clip = VertexStage(f, glm::vec3(1.0f + 0x1p-12f, 0.0f, 0.0f));
  CHECK(clip.x == 0.0f);
}
