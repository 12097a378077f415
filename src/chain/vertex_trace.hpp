// One vertex followed through every space of the chain, object to framebuffer, in double; and
// the chapter's own step-by-step route (Listing 10-3) to check the matrices against.
#pragma once

#include "chain/matrices.hpp"
#include "scene/scene.hpp"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

namespace twinraster {

struct VertexTrace {
  glm::dvec3 object;       // as the model lists it
  glm::dvec3 world;        // M_Model · V
  glm::dvec3 camera;       // M_Camera · world: camera at the origin looking along +Z
  glm::dvec4 clip;         // M_Projection · camera: Vulkan's clip space, w = camera z
  glm::dvec3 ndc;          // clip.xyz / clip.w: x, y in [-1, 1], depth z in [0, 1] when visible
  glm::dvec2 canvas;       // the chapter's canvas: origin at the centre, +y up, in pixels
  glm::dvec3 framebuffer;  // Vulkan's: origin top-left, +y down, pixel centres at +0.5; z = depth
  bool inside = false;     // inside the clip volume (-w <= x, y <= w, 0 <= z <= w)
};

// -w <= x, y <= w and 0 <= z <= w: the vertex is drawn where it is, not clipped away.
bool InsideClipVolume(const glm::dvec4& clip);

VertexTrace TraceVertex(const Scene& scene, const Chain& chain, const glm::dmat4& model_matrix, glm::dvec3 vertex);

// Listing 10-3 and 10-4, one operation at a time, no matrices: scale, rotate, translate, then
// the camera (translate by -position, rotate by the inverse rotation), then the projection.
glm::dvec3 ApplyStep(glm::dvec3 vertex, const TransformStep& step);        // one step of a list
glm::dvec3 ApplyTransform(glm::dvec3 vertex, const Transform& transform);  // object -> world
glm::dvec3 ApplyCamera(glm::dvec3 world, const Camera& camera);            // world -> camera
// The chapter's ProjectVertex: (x·d·Cw / (z·Vw), y·d·Ch / (z·Vh)) on the canvas; for an
// orthographic viewport (x·Cw/Vw, y·Ch/Vh), whatever z.
glm::dvec2 ProjectVertex(glm::dvec3 camera_space, const Viewport& viewport, const Canvas& canvas);

}  // namespace twinraster
