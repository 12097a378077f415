// Normals for lighting: each lit triangle corner's model-space normal (from the file, or from the
// faces), and the normal matrix that takes normals to world space.
//
// Why not M_Model itself: a normal is not a point or a direction along the surface but the
// perpendicular to it, and M_Model keeps perpendicularity only when it scales every axis alike.
// For any tangent t (n·t = 0) to stay perpendicular after the transform, n must go by a matrix N
// with (N·n)·(M·t) = 0, that is N = (M⁻¹)ᵀ for the upper 3x3 M of M_Model (docs/normals.md works
// it through with numbers).
#pragma once

#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <vector>

namespace twinraster {

// The inverse transpose of M_Model's upper 3x3; nullopt when that is singular (a zero scale), or
// when its determinant or its entries leave the range of double, or its entries that of float (the
// renderers' type for it): the scene loader refuses the scales that would.
std::optional<glm::dmat3> NormalMatrix(const glm::dmat4& model_matrix);

// The normal of triangle (a, b, c), (b - a) × (c - a), unnormalised: its length is twice the area.
glm::dvec3 FaceNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Unit-length model-space normals for every corner of every triangle of a lit model:
//  - flat: the face normal at all three corners;
//  - Gouraud: the file's vn for a corner that names one; otherwise the area-weighted average of
//    the face normals around the vertex (each face weighs by its area, so slivers count little).
// A normal that comes out zero (a degenerate face alone at its vertex, or vn 0 0 0) falls back to
// the face normal, and stays zero only if that is zero too: such a triangle covers no pixels.
std::vector<std::array<glm::dvec3, 3>> CornerNormals(const Model& model, Shading shading);

}  // namespace twinraster
