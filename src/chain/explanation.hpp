// `explain`'s numbers for a scene, typed: the chapter's matrices by their names, and for each
// chosen instance its M_Model, F and traced vertices (object -> world -> camera -> clip -> NDC ->
// canvas -> framebuffer, with the light where the model is lit). It computes and does not
// format: explain_report/ (explain_text, explain_json, chain_page) writes it out.
#pragma once

#include "chain/frustum.hpp"
#include "chain/light_trace.hpp"
#include "chain/matrices.hpp"
#include "chain/vertex_trace.hpp"
#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>

#include <array>
#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace twinraster {

// Without an instance asked for, this many instances are traced (the first ones); the rest are counted.
inline constexpr std::size_t kExplainedInstances = 16;

// Which vertices of each explained instance are traced.
enum class ExplainVertices {
  kTraced,  // one: the vertex asked for, else the first inside the clip volume, else vertex 0
  kAll,     // every vertex, in the model's order
};

struct ExplainOptions {
  std::optional<std::size_t> instance;  // only this instance
  std::optional<std::size_t> vertex;    // the traced vertex of each instance (with kAll, the one marked traced)
  ExplainVertices vertices = ExplainVertices::kTraced;
};

// A traced vertex's light: which triangle corner's normal it shows (a vertex may have a
// different normal in each triangle: the first corner that uses it), and the trace.
struct VertexLight {
  std::size_t triangle = 0;
  int corner = 0;
  LightTrace trace;
};

struct TracedVertex {
  std::size_t index = 0;  // in the model's vertex list
  VertexTrace trace;
  std::optional<VertexLight> light;  // lit instances only, and only for a vertex some triangle uses
};

// An instance that is a copy in a grid: the grid (an instance of the file) and its (i, j, k) there.
struct GridCopy {
  const InstanceGrid* grid = nullptr;
  std::array<std::size_t, 3> ijk{};
};

// A step of a transform written as a list: its kind and its I_S, I_R or I_T.
struct StepExplanation {
  TransformStep::Kind kind = TransformStep::Kind::kScale;
  glm::dmat4 matrix{1.0};
  std::string label;  // TransformStep::label: a glTF node's name, or the chapter's mirror
};

struct InstanceExplanation {
  std::size_t index = 0;         // in the scene's instances, every grid copy counted
  const Model* model = nullptr;  // the scene's model the instance draws
  std::optional<GridCopy> grid_copy;
  // M_Model's factors. A transform written as a list has its steps, in the order applied, and
  // then `translation` alone, the grid's offset (the identity when the instance is no grid copy);
  // any other has M_Model = translation · rotation · scale.
  std::optional<std::vector<StepExplanation>> steps;
  glm::dmat4 scale{1.0}, rotation{1.0}, translation{1.0};  // I_S, I_R, I_T
  glm::dmat4 model_matrix{1.0};                            // M_Model
  glm::dmat4 f{1.0};                                       // F = M_Projection · M_Camera · M_Model
  bool lit = false;                                        // lighting applies (the model's shading)
  std::optional<glm::dmat3> normal_matrix;                 // lit, and M_Model's 3x3 invertible
  std::vector<TracedVertex> vertices;                      // as ExplainOptions::vertices chose
  std::size_t traced = 0;                                  // vertices[traced] is the one to follow
};

struct Explanation {
  const Scene* scene = nullptr;  // the scene explained: it must outlive the explanation
  ExplainOptions options;        // as asked, checked
  Chain chain;                   // M_Projection and M_Camera
  // M_Projection = canvas_to_clip · viewport_to_canvas · p, p perspective or orthographic as the
  // viewport says.
  glm::dmat4 p{1.0}, viewport_to_canvas{1.0}, canvas_to_clip{1.0};
  // M_Camera = camera_rotation_inverse · camera_translation_inverse (C_R⁻¹ · C_T⁻¹).
  glm::dmat4 camera_rotation_inverse{1.0}, camera_translation_inverse{1.0};
  Frustum camera_frustum, world_frustum;       // in camera space, and through M_Camera⁻¹ in the world
  bool lighting_used = false;                  // the scene has lighting and is not drawn as a wireframe
  std::vector<InstanceExplanation> instances;  // the one asked for, or the first kExplainedInstances
};

// The base colour the light scales at corner `corner` of triangle `triangle`: its vertex's colour
// when the model has vertex colours, else the triangle's.
Rgb8 CornerBase(const Model& model, std::size_t triangle, std::size_t corner);

// Throws UsageError when the instance or vertex asked for does not exist.
Explanation Explain(const Scene& scene, const ExplainOptions& options);

}  // namespace twinraster
