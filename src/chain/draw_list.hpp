// What both renderers draw: the models' vertex data and each instance's float matrix F, decided
// once on the host so that neither renderer recomputes anything.
#pragma once

#include "scene/scene.hpp"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster {

// One model's geometry in float, as uploaded to the GPU: shared vertices, indexed triangles and
// one flat colour per triangle (the chapter colours triangles, not vertices).
struct DrawMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Rgb8> colours;  // colours[i] belongs to triangles[i]
};

// One instance: which mesh, and F = M_Projection · M_Camera · M_Model composed in double and
// rounded to float once. glm stores it column-major, as GLSL expects.
struct DrawCall {
  std::uint32_t mesh = 0;
  glm::mat4 F{1.0f};
};

struct DrawList {
  std::uint32_t width = 0, height = 0;
  Rgb8 background;
  std::vector<DrawMesh> meshes;  // meshes[i] is the scene's models[i]
  std::vector<DrawCall> draws;   // in instance order; on equal depth the earlier draw keeps the pixel
  // Standard depth: clear to 1, test LESS. Reversed Z (the projection maps near to 1, far to 0):
  // clear to 0, test GREATER. Either way depth is D32_SFLOAT and written.
  bool reversed_z = false;
  // Triangle edges only (Vulkan's polygonMode LINE, 1 pixel wide), with the same depth test.
  bool wireframe = false;
};

DrawList BuildDrawList(const Scene& scene);

// What every renderer checks before drawing a list someone else built: a size in 1..kMaxCanvasSize,
// every draw naming an existing mesh, every triangle using existing vertices and having its colour.
// Throws std::invalid_argument naming the first problem.
void ValidateDrawList(const DrawList& list);

}  // namespace twinraster
