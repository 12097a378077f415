// The chapter's matrices (Computer Graphics from Scratch, ch. 10) in double precision: the
// instance, camera and projection transforms and their composition F.
//
// Conventions, as in the chapter: column vectors on the right (V' = F · V), camera space has the
// camera at the origin looking along +Z with +Y up and +X right (left-handed), the canvas has its
// origin at the centre and +Y up. glm stores matrices column-major; m[col][row].
//
// Rotations (the chapter's convention) are built by scene/rotation.hpp.
#pragma once

#include "scene/rotation.hpp"  // Rotation, which the chain builds on
#include "scene/scene.hpp"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

namespace twinraster {

// Builds a 4x4 from rows written as the chapter prints them.
glm::dmat4 FromRows(const double (&rows)[4][4]);

glm::dmat4 Translation(glm::dvec3 t);       // I_T, C_T
glm::dmat4 Rotation4(const glm::dmat3& r);  // I_R, C_R: the 3x3 with w kept
glm::dmat4 Scale(glm::dvec3 s);             // I_S

// One step of a transform written as a list: its I_S, I_R or I_T, or a glTF node's local matrix.
glm::dmat4 StepMatrix(const TransformStep& step);
// M_Model = I_T · I_R · I_S: scale, then rotate, then translate (Listing 10-4's order). For a
// transform written as a list, its steps come first, in the order written:
// M_Model = I_T · I_R · I_S · step_n · ... · step_1 (I_T, I_R, I_S then hold only a grid's offset).
glm::dmat4 ModelMatrix(const Transform& t);

// M_Camera = C_R⁻¹ · C_T⁻¹. A rotation's inverse is its transpose; a translation's is its negation.
glm::dmat4 CameraMatrix(const Camera& camera);

// The chapter's perspective projection P (x·d, y·d, z) extended to 4x4: the third row keeps
// depth, z' = A·z + B with A = far/(far-near), B = -far·near/(far-near), and w' = z. Reversed Z
// swaps the ends: A = -near/(far-near), B = far·near/(far-near).
glm::dmat4 PerspectiveMatrix(const Viewport& viewport, const Depth& depth);

// The orthographic P (Catlike's section 5.1): x and y kept whatever z, depth linear in z,
// z' = A·z + B with A = 1/(far-near), B = -near/(far-near) (reversed: A = -1/(far-near),
// B = far/(far-near)), and w' = 1: nothing is divided, so size does not fall off with distance.
glm::dmat4 OrthographicMatrix(const Depth& depth);
// P for the scene's projection: PerspectiveMatrix or OrthographicMatrix.
glm::dmat4 ProjectionP(const Viewport& viewport, const Depth& depth);
// The chapter's M: viewport units to canvas pixels, a 2D scale by Cw/Vw and Ch/Vh.
glm::dmat4 ViewportToCanvas(const Viewport& viewport, const Canvas& canvas);

// What Vulkan adds: canvas pixels to clip space, x by 2/Cw, and y by -2/Ch (Vulkan's +y is down).
glm::dmat4 CanvasToClip(const Canvas& canvas);

// M_Projection = CanvasToClip · ViewportToCanvas · P (docs/projection.md derives both kinds).
glm::dmat4 ProjectionMatrix(const Viewport& viewport, const Canvas& canvas, const Depth& depth);

// F = M_Projection · M_Camera · M_Model, all in double.
struct Chain {
  glm::dmat4 projection;  // M_Projection
  glm::dmat4 camera;      // M_Camera
};
Chain SceneChain(const Scene& scene);
glm::dmat4 InstanceMatrix(const Chain& chain, const Transform& instance);  // F for one instance

}  // namespace twinraster
