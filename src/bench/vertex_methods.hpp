// The four ways of computing clip-space positions that the benchmark sets side by side, each a
// real code path: precomposed F in double (the project's default), precomposed F in float, the
// chapter's step-by-step chain in float, and camera-relative composition.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"  // ClipPositions
#include "scene/scene.hpp"

#include <glm/vec4.hpp>

#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster::bench {

enum class VertexMethod {
  kComposeDouble,   // 1. F = M_Projection · M_Camera · M_Model in double, rounded to float once
  kComposeFloat,    // 2. every matrix in float and multiplied in float, as most tutorials do
  kStepsFloat,      // 3. Listing 10-3 per vertex in float: scale, rotate, translate, camera, project
  kCameraRelative,  // 4. translations taken relative to the camera in double, then composed
};
inline constexpr VertexMethod kAllMethods[] = {VertexMethod::kComposeDouble, VertexMethod::kComposeFloat,
                                               VertexMethod::kStepsFloat, VertexMethod::kCameraRelative};

std::string_view MethodName(VertexMethod method);  // "compose-f64", "compose-f32", "steps-f32", "camera-relative"

// The per-instance float matrix F of the methods that have one (1, 2, 4); method 3 has none.
std::vector<glm::mat4> InstanceMatrices(const Scene& scene, VertexMethod method);

cpu::ClipPositions TransformVertices(const Scene& scene, const DrawList& list, VertexMethod method);

}  // namespace twinraster::bench
