#include "chain/normals.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>

namespace twinraster {
namespace {

glm::dvec3 UnitOrZero(const glm::dvec3& v) {
  const double length = glm::length(v);
  return length > 0 && std::isfinite(length) ? v / length : glm::dvec3(0.0);
}

}  // namespace

std::optional<glm::dmat3> NormalMatrix(const glm::dmat4& model_matrix) {
  const glm::dmat3 m(model_matrix);
  const double det = glm::determinant(m);
  if (det == 0 || !std::isfinite(det)) return std::nullopt;
  const glm::dmat3 n = glm::transpose(glm::inverse(m));
  // The renderers take it in float: an entry beyond float's range would light with infinities.
  for (glm::length_t c = 0; c < 3; ++c) {
    for (glm::length_t r = 0; r < 3; ++r) {
      if (!std::isfinite(static_cast<float>(n[c][r]))) return std::nullopt;
    }
  }
  return n;
}

glm::dvec3 FaceNormal(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  return glm::cross(b - a, c - a);
}

std::vector<std::array<glm::dvec3, 3>> CornerNormals(const Model& model, Shading shading) {
  std::vector<std::array<glm::dvec3, 3>> corners(model.triangles.size());
  const auto face = [&](const Triangle& t) {
    return FaceNormal(model.vertices[t.v[0]], model.vertices[t.v[1]], model.vertices[t.v[2]]);
  };
  if (shading == Shading::kFlat) {
    for (std::size_t i = 0; i < corners.size(); ++i) {
      const glm::dvec3 n = UnitOrZero(face(model.triangles[i]));
      corners[i] = {n, n, n};
    }
    return corners;
  }
  // Area-weighted vertex normals, computed only if some corner has no vn.
  std::vector<glm::dvec3> averaged;
  const auto from_file = [&](std::size_t t, int k) -> const glm::dvec3* {
    if (t >= model.triangle_normals.size()) return nullptr;
    const std::uint32_t index = model.triangle_normals[t][static_cast<std::size_t>(k)];
    return index == kNoNormal ? nullptr : &model.normals[index];
  };
  for (std::size_t t = 0; t < corners.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const glm::dvec3* given = from_file(t, k);
      glm::dvec3 n = given ? UnitOrZero(*given) : glm::dvec3(0.0);
      if (!given) {
        if (averaged.empty()) {
          averaged.assign(model.vertices.size(), glm::dvec3(0.0));
          for (const Triangle& tri : model.triangles) {
            const glm::dvec3 f = face(tri);
            for (std::uint32_t v : tri.v) averaged[v] += f;
          }
        }
        n = UnitOrZero(averaged[model.triangles[t].v[static_cast<std::size_t>(k)]]);
      }
      if (n == glm::dvec3(0.0)) n = UnitOrZero(face(model.triangles[t]));
      corners[t][static_cast<std::size_t>(k)] = n;
    }
  }
  return corners;
}

}  // namespace twinraster
