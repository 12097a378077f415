// One vertex's light followed step by step in double, for `explain` and docs/normals.md: its
// normal through the normal matrix (and, to show why, through M_Model itself), then each light's
// term of the book's diffuse sum, then the colour.
#pragma once

#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace twinraster {

struct LightTerm {
  glm::dvec3 l{0.0};        // from the surface toward the light
  double n_dot_l = 0;       // with the unit world normal
  double contribution = 0;  // intensity · max(0, n·l) / |l|
};

struct LightTrace {
  glm::dvec3 object_normal{0.0};  // as the model (or the chain's face average) gives it
  glm::dvec3 world_normal{0.0};   // N · n, N = (M_Model's upper 3x3)⁻ᵀ
  glm::dvec3 unit_normal{0.0};    // renormalised
  glm::dvec3 wrong_normal{0.0};   // M_Model · n, renormalised: what transforming by M would give
  glm::dvec3 world{0.0};          // the surface point, M_Model · V
  double ambient = 0;
  std::vector<LightTerm> terms;  // one per light, in the scene's order
  double intensity = 0;          // I = ambient + the terms
  glm::dvec3 colour{0.0};        // base / 255 · min(I, 1), each channel in [0, 1]
};

// `normal_matrix` is NormalMatrix(model_matrix) (the caller has checked that it exists).
LightTrace TraceLight(const Lighting& lighting, const glm::dmat4& model_matrix, const glm::dmat3& normal_matrix,
                      const glm::dvec3& position, const glm::dvec3& normal, Rgb8 base);

}  // namespace twinraster
