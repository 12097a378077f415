// What both renderers draw: the models' vertex data and each instance's float matrix F, decided
// once on the host so that neither renderer recomputes anything.
#pragma once

#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <optional>
#include <vector>

namespace twinraster {

// One model's geometry in float, as uploaded to the GPU: shared vertices, indexed triangles and
// one flat colour per triangle (the chapter colours triangles, not vertices). A lit mesh adds a
// model-space unit normal per triangle corner (chain/normals.hpp says which), and its triangle
// colours become the base colours the light scales. A mesh with vertex colours fills each corner
// with its vertex's colour instead (unlit: k / 255, interpolated as Gouraud colours are; lit: the
// vertex's colour is its base colour); its triangle colours are then unused.
struct DrawMesh {
  std::vector<glm::vec3> positions;
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<Rgb8> colours;  // colours[i] belongs to triangles[i]
  Shading shading = Shading::kUnlit;
  std::vector<std::array<glm::vec3, 3>> normals;  // lit only: normals[i][k], corner k of triangles[i]
  // Empty, or vertex_colours[i] belongs to positions[i]; always empty in a wireframe list.
  std::vector<Rgb8> vertex_colours;
  // Whether its colour varies across a triangle: lit, or vertex-coloured (else one flat colour).
  bool smooth() const { return shading != Shading::kUnlit || !vertex_colours.empty(); }
};

// One instance: which mesh, and F = M_Projection · M_Camera · M_Model composed in double and
// rounded to float once. glm stores it column-major, as GLSL expects.
struct DrawCall {
  std::uint32_t mesh = 0;
  glm::mat4 F{1.0f};
};

// A light as the vertex shader reads it, in world space (scene.hpp's Light, rounded to float).
struct DrawLight {
  glm::vec3 vector{0.0f};  // directional: toward the light; point: its position
  float intensity = 0;
  bool point = false;
};

// What lighting needs of one instance beyond F, each composed in double and rounded once:
// M_Model, for the world position a point light is seen from, and the normal matrix
// N = (M_Model's upper 3x3)⁻ᵀ, for the normal (zero for an instance of an unlit mesh, which
// may be singular).
struct LitInstance {
  glm::mat4x3 model{1.0f};  // the upper three rows of M_Model; column 3 is the translation
  glm::mat3 normal{1.0f};
};

// The scene's light: the ambient term, the lights in the order the sum adds them, and one
// LitInstance per draw.
struct DrawLighting {
  float ambient = 0;
  std::vector<DrawLight> lights;
  std::vector<LitInstance> instances;  // instances[i] belongs to draws[i]
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
  // Edges are not lit: a wireframe list has no lighting and every mesh is unlit, in its triangle
  // colours (no vertex colours).
  bool wireframe = false;
  // Present when some mesh is lit; absent, the list holds flat colours only.
  std::optional<DrawLighting> lighting;
};

DrawList BuildDrawList(const Scene& scene);

// What every renderer checks before drawing a list someone else built: a size in 1..kMaxCanvasSize,
// every draw naming an existing mesh, every triangle using existing vertices and having its colour,
// a lit mesh having its normals, vertex colours none or one per vertex (none in a wireframe), and
// lighting covering every draw.
// Throws std::invalid_argument naming the first problem.
void ValidateDrawList(const DrawList& list);

}  // namespace twinraster
