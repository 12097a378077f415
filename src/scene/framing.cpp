#include "scene/framing.hpp"

#include "scene/rotation.hpp"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace twinraster {

namespace {

// The bounding sphere's share of the viewport's half-width (and height): 80 %, a margin of 10 %
// of the canvas on every side.
constexpr double kFill = 0.8;
// Near and far sit this much beyond the sphere, so that no vertex lies on a clipping plane.
constexpr double kDepthMargin = 1.1;

}  // namespace

Sphere BoundingSphere(const PointWalk& walk) {
  glm::dvec3 low(std::numeric_limits<double>::infinity()), high(-std::numeric_limits<double>::infinity());
  walk([&](const glm::dvec3& p) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  });
  Sphere sphere;
  if (!(low.x <= high.x)) return sphere;  // no point at all
  sphere.centre = (low + high) / 2.0;
  walk([&](const glm::dvec3& p) { sphere.radius = std::max(sphere.radius, glm::length(p - sphere.centre)); });
  const double scale = std::max({1.0, std::abs(sphere.centre.x), std::abs(sphere.centre.y), std::abs(sphere.centre.z)});
  sphere.radius = std::max(sphere.radius, 1e-6 * scale);
  return sphere;
}

Lighting Headlight(const glm::dvec3& toward_eye) {
  // l points from the surface toward the light, here toward the camera.
  return Lighting{0.1, {Light{Light::Kind::kDirectional, toward_eye, 0.9}}};
}

void FrameAsset(const Sphere& sphere, Scene& scene) {
  const glm::dvec3 centre = sphere.centre * kMirror;
  const glm::dvec3 toward_eye = glm::dvec3(1, 1, 3) * kMirror;
  // The sphere's silhouette, seen from distance D, is a circle of angular radius asin(r / D);
  // its tangent must be kFill times the viewport's half-width over d (0.5 / 1).
  const double tangent = kFill * 0.5;
  const double distance = sphere.radius * std::sqrt(1 + tangent * tangent) / tangent;  // r / sin
  const glm::dvec3 eye = centre + distance * glm::normalize(toward_eye);

  scene.canvas = Canvas{800, 800, Rgb8{40, 40, 48}};
  scene.viewport = Viewport{1, 1, 1, Projection::kPerspective};
  scene.depth.near = distance - kDepthMargin * sphere.radius;
  scene.depth.far = distance + kDepthMargin * sphere.radius;
  scene.camera = CameraLookingAt(eye, centre, glm::dvec3(0, 1, 0));
  scene.lighting = Headlight(toward_eye);
}

}  // namespace twinraster
