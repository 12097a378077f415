// Stage 1, the vertex shader: clip = F · (p, 1), summed in exactly the order the GPU shader writes
// it, ((F[0]*p.x + F[1]*p.y) + F[2]*p.z) + F[3] with F[i] column i, every operation rounded to
// float (lavapipe lowers fused multiply-adds in shaders, and this file is built without
// contraction).
#pragma once

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace twinraster::cpu {

glm::vec4 VertexStage(const glm::mat4& f, const glm::vec3& p);

}  // namespace twinraster::cpu
