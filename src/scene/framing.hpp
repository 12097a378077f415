// How an asset that brings no camera is seen (an OBJ file, a glTF file without a camera node), as
// tinyrenderer's command line sees a model: a camera placed from the points the asset draws, the
// canvas, the depth range and a headlight. It does not read files; obj_scene and gltf_scene do.
#pragma once

#include "scene/scene.hpp"

#include <glm/vec3.hpp>

#include <functional>

namespace twinraster {

struct Sphere {
  glm::dvec3 centre{0.0};
  double radius = 0;
};

// Calls `point` once for every point the asset draws, in the asset's own right-handed frame.
using PointWalk = std::function<void(const std::function<void(const glm::dvec3&)>& point)>;

// Around the centre of the points' bounding box, with the radius that reaches the farthest of
// them (two walks: nothing is stored). A single point still gets a radius: a millionth of its
// distance from the origin, or of 1.
Sphere BoundingSphere(const PointWalk& walk);

// Sets the canvas (800 x 800, a dark background), the viewport, the depth range that hugs the
// sphere, the camera and a headlight. The asset is seen from the direction (1, 1, 3) of its own
// right-handed frame, from far enough that the sphere fills 80 % of the canvas. The chapter's
// world is left-handed: every instance of the asset must mirror z (kMirror), as this camera is
// placed in the mirrored world.
void FrameAsset(const Sphere& sphere, Scene& scene);

// z mirrored: a right-handed asset's frame to the chapter's left-handed world.
inline constexpr glm::dvec3 kMirror{1, 1, -1};

// The headlight: ambient 0.1 and a directional light of 0.9 toward `toward_eye` (world space).
Lighting Headlight(const glm::dvec3& toward_eye);

}  // namespace twinraster
