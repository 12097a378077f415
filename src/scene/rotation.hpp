// Rotations as a scene describes them: about an axis by an angle (optionally reached in many
// rounded steps), and a camera placed by eye, center and up. The scene stores the resulting 3x3.
//
// Rotation convention: Rotation(axis, θ) is the chapter demo's matrix. About Y it is
//   [ cos θ  0  -sin θ ]
//   [   0    1    0    ]
//   [ sin θ  0   cos θ ]
// which turns +X toward +Z. X and Z follow the same handedness: +Y toward +X about Z, +Z toward
// +Y about X. This is the transpose of the right-hand-rule matrix, so Catlike Coding's (Unity's)
// rotation by θ is this project's rotation by -θ.
#pragma once

#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

namespace twinraster {

// Rotation about a unit-length axis by `degrees`, chapter convention (see above).
glm::dmat3 Rotation(glm::dvec3 axis, double degrees);

// The same rotation with the entries the chapter's demos compute, cos and sin of the double
// degrees·π/180 (base/trigonometry.hpp), for --rules book: where the demos round θ·π/180 first,
// 180° has sin 1.2e-16, not 0.
glm::dmat3 BookRotation(glm::dvec3 axis, double degrees);

// The same rotation reached the way an animated camera reaches it: `steps` small rotations by
// degrees/steps multiplied one after another, each product rounded, optionally re-orthonormalized
// (Gram-Schmidt) after every step. Shows how rounding drifts a rotation away from orthonormal.
glm::dmat3 AccumulatedRotation(glm::dvec3 axis, double degrees, int steps, bool reorthonormalize);

// tinyrenderer's lookat re-expressed in the chapter's camera convention: the camera sits at `eye`
// and looks along +Z toward `center`, with +Y as close to `up` as possible. Callers have checked
// that eye != center and that up is not parallel to the view direction.
Camera CameraLookingAt(glm::dvec3 eye, glm::dvec3 center, glm::dvec3 up);

}  // namespace twinraster
