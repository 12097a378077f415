#include "bench/vertex_methods.hpp"

#include "chain/matrices.hpp"
#include "cpu/vertex_stage.hpp"

#include <glm/matrix.hpp>

#include <stdexcept>

namespace twinraster::bench {

namespace {

glm::mat4 ToFloat(const glm::dmat4& m) { return glm::mat4(m); }
glm::mat3 ToFloat(const glm::dmat3& m) { return glm::mat3(m); }
glm::vec3 ToFloat(const glm::dvec3& v) { return glm::vec3(v); }

// Method 2: each of the chapter's matrices rounded to float as it is built, every product in float.
glm::mat4 ComposeInFloat(const Scene& scene, const Transform& t) {
  const glm::mat4 projection = ToFloat(ProjectionP(scene.viewport, scene.depth));
  const glm::mat4 to_canvas = ToFloat(ViewportToCanvas(scene.viewport, scene.canvas));
  const glm::mat4 to_clip = ToFloat(CanvasToClip(scene.canvas));
  const glm::mat4 camera =
      ToFloat(Rotation4(glm::transpose(scene.camera.rotation))) * ToFloat(Translation(-scene.camera.position));
  glm::mat4 model = ToFloat(Translation(t.translation)) * ToFloat(Rotation4(t.rotation)) * ToFloat(Scale(t.scale));
  if (t.steps) {
    glm::mat4 listed(1.0f);
    for (const TransformStep& step : *t.steps) listed = ToFloat(StepMatrix(step)) * listed;
    model = model * listed;
  }
  return to_clip * to_canvas * projection * camera * model;
}

// Method 4: the camera's position is subtracted from each instance's translation in double, so
// that nothing composed afterwards carries the large absolute coordinates.
glm::mat4 CameraRelative(const Scene& scene, const Transform& t) {
  const glm::dmat4 projection = ProjectionMatrix(scene.viewport, scene.canvas, scene.depth);
  const glm::dmat4 camera_rotation = Rotation4(glm::transpose(scene.camera.rotation));
  glm::dmat4 model = ModelMatrix(t);
  model[3] -= glm::dvec4(scene.camera.position, 0.0);  // the same bits as T(t - c) · R · S
  return ToFloat(projection * camera_rotation * model);
}

// Method 3: Listing 10-3's ApplyTransform, the camera and the projection, one step at a time in float.
glm::vec4 StepsInFloat(glm::vec3 v, const Transform& t, const Scene& scene, const glm::mat4& projection) {
  if (t.steps) {  // a transform written as a list: its steps first, each in float
    for (const TransformStep& step : *t.steps) {
      switch (step.kind) {
        case TransformStep::Kind::kScale: v = v * ToFloat(step.vector); break;
        case TransformStep::Kind::kRotation: v = ToFloat(step.rotation) * v; break;
        case TransformStep::Kind::kTranslation: v = v + ToFloat(step.vector); break;
        case TransformStep::Kind::kMatrix: v = glm::vec3(ToFloat(step.matrix) * glm::vec4(v, 1.0f)); break;
      }
    }
  }
  const glm::vec3 scaled = v * ToFloat(t.scale);
  const glm::vec3 rotated = ToFloat(t.rotation) * scaled;
  const glm::vec3 world = rotated + ToFloat(t.translation);
  const glm::vec3 translated = world - ToFloat(scene.camera.position);
  const glm::vec3 camera = glm::transpose(ToFloat(scene.camera.rotation)) * translated;
  return cpu::VertexStage(projection, camera);
}

}  // namespace

std::string_view MethodName(VertexMethod method) {
  switch (method) {
    case VertexMethod::kComposeDouble: return "compose-f64";
    case VertexMethod::kComposeFloat: return "compose-f32";
    case VertexMethod::kStepsFloat: return "steps-f32";
    case VertexMethod::kCameraRelative: return "camera-relative";
  }
  return "?";
}

std::vector<glm::mat4> InstanceMatrices(const Scene& scene, VertexMethod method) {
  std::vector<glm::mat4> matrices;
  const Chain chain = SceneChain(scene);
  for (const Instance& instance : scene.instances) {
    switch (method) {
      case VertexMethod::kComposeDouble: matrices.push_back(ToFloat(InstanceMatrix(chain, instance.transform))); break;
      case VertexMethod::kComposeFloat: matrices.push_back(ComposeInFloat(scene, instance.transform)); break;
      case VertexMethod::kCameraRelative: matrices.push_back(CameraRelative(scene, instance.transform)); break;
      case VertexMethod::kStepsFloat: throw std::logic_error("steps-f32 has no instance matrix");
    }
  }
  return matrices;
}

cpu::ClipPositions TransformVertices(const Scene& scene, const DrawList& list, VertexMethod method) {
  cpu::ClipPositions clip(list.draws.size());
  if (method == VertexMethod::kStepsFloat) {
    const glm::mat4 projection = ToFloat(ProjectionMatrix(scene.viewport, scene.canvas, scene.depth));
    for (std::size_t d = 0; d < list.draws.size(); ++d) {
      const Transform& t = scene.instances[d].transform;
      for (const glm::vec3& p : list.meshes[list.draws[d].mesh].positions)
        clip[d].push_back(StepsInFloat(p, t, scene, projection));
    }
    return clip;
  }
  const std::vector<glm::mat4> f = InstanceMatrices(scene, method);
  for (std::size_t d = 0; d < list.draws.size(); ++d) {
    for (const glm::vec3& p : list.meshes[list.draws[d].mesh].positions) clip[d].push_back(cpu::VertexStage(f[d], p));
  }
  return clip;
}

}  // namespace twinraster::bench
