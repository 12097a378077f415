#include "chain/vertex_trace.hpp"

#include <glm/matrix.hpp>

namespace twinraster {

VertexTrace TraceVertex(const Scene& scene, const Chain& chain, const glm::dmat4& model_matrix, glm::dvec3 vertex) {
  VertexTrace t;
  t.object = vertex;
  t.world = glm::dvec3(model_matrix * glm::dvec4(vertex, 1.0));
  t.camera = glm::dvec3(chain.camera * glm::dvec4(t.world, 1.0));
  t.clip = chain.projection * glm::dvec4(t.camera, 1.0);
  t.ndc = glm::dvec3(t.clip) / t.clip.w;

  // Undo CanvasToClip to recover the chapter's canvas; Vulkan's viewport transform (x, y) =
  // (ndc + 1) · size / 2 gives the framebuffer, whose +y points down.
  const double half_w = scene.canvas.width / 2.0, half_h = scene.canvas.height / 2.0;
  t.canvas = glm::dvec2(t.ndc.x * half_w, -t.ndc.y * half_h);
  t.framebuffer = glm::dvec3((t.ndc.x + 1.0) * half_w, (t.ndc.y + 1.0) * half_h, t.ndc.z);

  t.inside = InsideClipVolume(t.clip);
  return t;
}

bool InsideClipVolume(const glm::dvec4& c) {
  return -c.w <= c.x && c.x <= c.w && -c.w <= c.y && c.y <= c.w && 0 <= c.z && c.z <= c.w;
}

glm::dvec3 ApplyStep(glm::dvec3 vertex, const TransformStep& step) {
  switch (step.kind) {
    case TransformStep::Kind::kScale: return vertex * step.vector;
    case TransformStep::Kind::kRotation: return step.rotation * vertex;
    case TransformStep::Kind::kTranslation: return vertex + step.vector;
    case TransformStep::Kind::kMatrix: return glm::dvec3(step.matrix * glm::dvec4(vertex, 1.0));
  }
  return vertex;
}

glm::dvec3 ApplyTransform(glm::dvec3 vertex, const Transform& transform) {
  if (transform.steps) {
    for (const TransformStep& step : *transform.steps) vertex = ApplyStep(vertex, step);
  }
  const glm::dvec3 scaled = vertex * transform.scale;
  const glm::dvec3 rotated = transform.rotation * scaled;
  return rotated + transform.translation;
}

glm::dvec3 ApplyCamera(glm::dvec3 world, const Camera& camera) {
  const glm::dvec3 translated = world - camera.position;
  return glm::transpose(camera.rotation) * translated;
}

glm::dvec2 ProjectVertex(glm::dvec3 v, const Viewport& viewport, const Canvas& canvas) {
  if (viewport.projection == Projection::kOrthographic) {
    return glm::dvec2(v.x * canvas.width / viewport.width, v.y * canvas.height / viewport.height);
  }
  const double d = viewport.distance;
  return glm::dvec2(v.x * d * canvas.width / (v.z * viewport.width), v.y * d * canvas.height / (v.z * viewport.height));
}

}  // namespace twinraster
