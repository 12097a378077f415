#include "chain/light_trace.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace twinraster {

LightTrace TraceLight(const Lighting& lighting, const glm::dmat4& model_matrix, const glm::dmat3& normal_matrix,
                      const glm::dvec3& position, const glm::dvec3& normal, Rgb8 base) {
  LightTrace t;
  t.object_normal = normal;
  t.world = glm::dvec3(model_matrix * glm::dvec4(position, 1.0));
  t.world_normal = normal_matrix * normal;
  const double length = glm::length(t.world_normal);
  t.unit_normal = length > 0 ? t.world_normal / length : glm::dvec3(0.0);
  const glm::dvec3 wrong = glm::dmat3(model_matrix) * normal;
  const double wrong_length = glm::length(wrong);
  t.wrong_normal = wrong_length > 0 ? wrong / wrong_length : glm::dvec3(0.0);
  t.ambient = lighting.ambient;
  t.intensity = lighting.ambient;
  for (const Light& light : lighting.lights) {
    LightTerm term;
    term.l = light.kind == Light::Kind::kPoint ? light.vector - t.world : light.vector;
    term.n_dot_l = glm::dot(t.unit_normal, term.l);
    const double l_length = glm::length(term.l);
    if (term.n_dot_l > 0 && l_length > 0) term.contribution = light.intensity * term.n_dot_l / l_length;
    t.intensity += term.contribution;
    t.terms.push_back(term);
  }
  const double scale = std::min(t.intensity, 1.0);
  t.colour = glm::dvec3(base.r, base.g, base.b) / 255.0 * scale;
  return t;
}

}  // namespace twinraster
