#include "book/book_chain.hpp"

#include <cmath>

namespace twinraster::book {

Mat4x4 Identity4x4() { return {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}}}; }

Mat4x4 MultiplyMM4(const Mat4x4& a, const Mat4x4& b) {
  Mat4x4 result{};  // zeros: the first addition is 0 + a0·b0, as in the demo
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j)
      for (std::size_t k = 0; k < 4; ++k) result[i][j] += a[i][k] * b[k][j];
  return result;
}

Vertex4 MultiplyMV(const Mat4x4& m, const Vertex4& v) {
  Vertex4 result{};
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) result[i] += m[i][j] * v[j];
  return result;
}

Mat4x4 Transposed(const Mat4x4& m) {
  Mat4x4 result{};
  for (std::size_t i = 0; i < 4; ++i)
    for (std::size_t j = 0; j < 4; ++j) result[i][j] = m[j][i];
  return result;
}

Mat4x4 MakeTranslationMatrix(glm::dvec3 translation) {
  return {{{1, 0, 0, translation.x}, {0, 1, 0, translation.y}, {0, 0, 1, translation.z}, {0, 0, 0, 1}}};
}

Mat4x4 MakeScalingMatrix(glm::dvec3 scale) {
  return {{{scale.x, 0, 0, 0}, {0, scale.y, 0, 0}, {0, 0, scale.z, 0}, {0, 0, 0, 1}}};
}

Mat4x4 MakeOrientationMatrix(const glm::dmat3& rotation) {
  Mat4x4 m = Identity4x4();
  for (glm::length_t row = 0; row < 3; ++row)
    for (glm::length_t column = 0; column < 3; ++column) {
      m[static_cast<std::size_t>(row)][static_cast<std::size_t>(column)] = rotation[column][row];  // glm: [column][row]
    }
  for (std::size_t axis = 0; axis < 3; ++axis) {
    bool fixed = std::abs(m[axis][axis] - 1.0) <= 0x1p-50;
    for (std::size_t other = 0; other < 3; ++other) {
      if (other != axis && (m[axis][other] != 0.0 || m[other][axis] != 0.0)) fixed = false;
    }
    if (fixed) m[axis][axis] = 1.0;
  }
  return m;
}

Mat4x4 MakeInstanceTransform(const Transform& transform) {
  return MultiplyMM4(
      MakeTranslationMatrix(transform.translation),
      MultiplyMM4(MakeOrientationMatrix(transform.book_rotation ? *transform.book_rotation : transform.rotation),
                  MakeScalingMatrix(transform.scale)));
}

Mat4x4 MakeCameraMatrix(const Camera& camera) {
  // The demo negates the position as -1·p, which is exact: the same as glm's unary minus.
  return MultiplyMM4(Transposed(MakeOrientationMatrix(camera.book_rotation ? *camera.book_rotation : camera.rotation)),
                     MakeTranslationMatrix(-camera.position));
}

}  // namespace twinraster::book
