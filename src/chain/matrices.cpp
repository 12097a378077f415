#include "chain/matrices.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <cmath>
#include <numbers>

namespace twinraster {

glm::dmat4 FromRows(const double (&rows)[4][4]) {
  glm::dmat4 m(0.0);
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) m[c][r] = rows[r][c];
  return m;
}

glm::dmat4 Translation(glm::dvec3 t) {
  return FromRows({{1, 0, 0, t.x}, {0, 1, 0, t.y}, {0, 0, 1, t.z}, {0, 0, 0, 1}});
}

glm::dmat4 Rotation4(const glm::dmat3& r) {
  return FromRows(
      {{r[0][0], r[1][0], r[2][0], 0}, {r[0][1], r[1][1], r[2][1], 0}, {r[0][2], r[1][2], r[2][2], 0}, {0, 0, 0, 1}});
}

glm::dmat4 Scale(glm::dvec3 s) { return FromRows({{s.x, 0, 0, 0}, {0, s.y, 0, 0}, {0, 0, s.z, 0}, {0, 0, 0, 1}}); }

glm::dmat4 StepMatrix(const TransformStep& step) {
  switch (step.kind) {
    case TransformStep::Kind::kScale: return Scale(step.vector);
    case TransformStep::Kind::kRotation: return Rotation4(step.rotation);
    case TransformStep::Kind::kTranslation: return Translation(step.vector);
    case TransformStep::Kind::kMatrix: return step.matrix;
  }
  return glm::dmat4(1.0);
}

glm::dmat4 ModelMatrix(const Transform& t) {
  const glm::dmat4 object_form = Translation(t.translation) * Rotation4(t.rotation) * Scale(t.scale);
  if (!t.steps) return object_form;
  glm::dmat4 listed(1.0);
  for (const TransformStep& step : *t.steps) listed = StepMatrix(step) * listed;  // each applied after the last
  return object_form * listed;
}

glm::dmat4 CameraMatrix(const Camera& camera) {
  return Rotation4(glm::transpose(camera.rotation)) * Translation(-camera.position);
}

glm::dmat4 PerspectiveMatrix(const Viewport& viewport, const Depth& depth) {
  const double d = viewport.distance, n = depth.near, f = depth.far;
  // depth = A + B/z: 0 at near and 1 at far, or reversed, 1 at near and 0 at far. An infinite far
  // (a glTF camera without zfar) takes the limit: A = 1, B = -near (reversed: A = 0, B = near).
  const bool infinite = std::isinf(f);
  const double a = infinite ? (depth.reversed ? 0.0 : 1.0) : depth.reversed ? -n / (f - n) : f / (f - n);
  const double b = infinite ? (depth.reversed ? n : -n) : depth.reversed ? f * n / (f - n) : -f * n / (f - n);
  return FromRows({{d, 0, 0, 0}, {0, d, 0, 0}, {0, 0, a, b}, {0, 0, 1, 0}});
}

glm::dmat4 OrthographicMatrix(const Depth& depth) {
  const double n = depth.near, f = depth.far;
  // depth = A·z + B: 0 at near and 1 at far, or reversed, 1 at near and 0 at far.
  const double a = depth.reversed ? -1 / (f - n) : 1 / (f - n);
  const double b = depth.reversed ? f / (f - n) : -n / (f - n);
  return FromRows({{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, a, b}, {0, 0, 0, 1}});
}

glm::dmat4 ProjectionP(const Viewport& viewport, const Depth& depth) {
  return viewport.projection == Projection::kOrthographic ? OrthographicMatrix(depth)
                                                          : PerspectiveMatrix(viewport, depth);
}

glm::dmat4 ViewportToCanvas(const Viewport& viewport, const Canvas& canvas) {
  const double sx = canvas.width / viewport.width, sy = canvas.height / viewport.height;
  return FromRows({{sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
}

glm::dmat4 CanvasToClip(const Canvas& canvas) {
  const double sx = 2.0 / canvas.width, sy = -2.0 / canvas.height;
  return FromRows({{sx, 0, 0, 0}, {0, sy, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
}

glm::dmat4 ProjectionMatrix(const Viewport& viewport, const Canvas& canvas, const Depth& depth) {
  return CanvasToClip(canvas) * ViewportToCanvas(viewport, canvas) * ProjectionP(viewport, depth);
}

Chain SceneChain(const Scene& scene) {
  return Chain{ProjectionMatrix(scene.viewport, scene.canvas, scene.depth), CameraMatrix(scene.camera)};
}

glm::dmat4 InstanceMatrix(const Chain& chain, const Transform& instance) {
  return chain.projection * chain.camera * ModelMatrix(instance);
}

}  // namespace twinraster
