// The chapter demo's matrix arithmetic (raster-08), operation for operation in double, so that
// every matrix entry and every camera-space vertex is the demo's own number.
//
// The demo keeps matrices as rows ([row][column]) and sums each entry left to right from 0:
// ((((0 + a0·b0) + a1·b1) + a2·b2) + a3·b3), every step rounded. glm's operator* and the chain
// stage (chain/matrices.hpp) may add in another order, which is why the book keeps its own.
#pragma once

#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <array>

namespace twinraster::book {

using Mat4x4 = std::array<std::array<double, 4>, 4>;  // [row][column], as the demo writes it
using Vertex4 = std::array<double, 4>;                // x, y, z, w

Mat4x4 Identity4x4();
Mat4x4 MultiplyMM4(const Mat4x4& a, const Mat4x4& b);   // a · b, each entry summed over k = 0..3
Vertex4 MultiplyMV(const Mat4x4& m, const Vertex4& v);  // m · v, each row summed over j = 0..3
Mat4x4 Transposed(const Mat4x4& m);

Mat4x4 MakeTranslationMatrix(glm::dvec3 translation);
// The demo scales uniformly; a scene may scale each axis, so the diagonal is (sx, sy, sz, 1).
Mat4x4 MakeScalingMatrix(glm::dvec3 scale);

// The demo's 4x4 orientation for a scene's 3x3 rotation (scene/rotation.hpp: the same layout as
// the demo's MakeOYRotationMatrix, rows [cos, 0, -sin] [0, 1, 0] [sin, 0, cos] about Y).
// The loader builds Rotation(axis, θ) by Rodrigues' formula, whose entry on the axis is
// cos θ + (1 - cos θ): for about one angle in nine (195° and -30° are not among them) that sum
// rounds to 1 - 2⁻⁵³ where the demo writes 1. So an axis that the matrix leaves fixed (its row
// and column zero off the diagonal, the diagonal within 2⁻⁵⁰ of 1) gets exactly 1; every other
// entry is the scene's; the callers pass the loader's book_rotation where it has one, whose
// entries are the demo's cos and sin of θ·π/180.
Mat4x4 MakeOrientationMatrix(const glm::dmat3& rotation);

// The instance's transform as the demo's Instance builds it: T(position) · (orientation · S(scale)).
Mat4x4 MakeInstanceTransform(const Transform& transform);

// The chapter's MakeCameraMatrix as the demo computes it: Transposed(orientation) · T(-position).
Mat4x4 MakeCameraMatrix(const Camera& camera);

}  // namespace twinraster::book
