// The ground truth: the scene's transform chain and rasterization evaluated in double precision
// with no float rounding and no subpixel snapping, the reference that defines "error".
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstdint>
#include <vector>

namespace twinraster::truth {

// Clip-space positions in double for one draw: clip[i] = F_double · (mesh vertex i, 1), where
// F_double is the instance's matrix composed in double and never rounded to float. One vector per
// DrawList::draws entry.
using ExactClipPositions = std::vector<std::vector<glm::dvec4>>;

// The host chain in double (SceneChain, InstanceMatrix) applied to the Scene's double vertices.
ExactClipPositions ExactClipSpace(const Scene& scene);

// The scene's light in double, one instance at a time (so memory stays bounded by one mesh):
// each lit triangle corner's colour in [0, 1] from the double M_Model, normal matrix, normals
// and lights (chain/light_trace.hpp), corner 0's for all three of a flat triangle. A corner's base
// colour is its vertex's when the model has vertex colours; an unlit vertex-coloured corner's
// colour is that base itself, k / 255.
class ExactLight {
 public:
  explicit ExactLight(const Scene& scene);  // keeps a reference to `scene`
  // Empty for an instance of an unlit model without vertex colours (or of any model in a
  // wireframe scene).
  std::vector<std::array<glm::dvec3, 3>> CornerColours(std::size_t instance) const;

 private:
  const Scene* scene_;
  std::vector<std::vector<std::array<glm::dvec3, 3>>> normals_;  // per model, lit ones only
};

// The truth image, and per pixel which triangle it shows: 0 for the background, else 1 + the
// triangle's number counting every draw's triangles in list order (draw 0's first).
struct TruthImage {
  Image image;
  std::vector<std::uint64_t> surfaces;
};

// The ground truth image: same topology, colours, canvas size, background and depth mode
// (DrawList::reversed_z: clear 0, GREATER; else clear 1, LESS) as `list`, but positions from
// `clip`. Clipping, viewport transform, coverage at pixel centres (top-left rule on exact ties)
// and depth all in double. Lit meshes take their colours from `light` (required when the list has
// lighting), interpolated perspective-correctly, each channel round(clamp(c, 0, 1) · 255) to
// nearest, ties to even; unlit meshes keep their flat colours, as in a list with no lighting at
// all (tests/truth/unlit_unchanged_test.cpp). Throws std::invalid_argument for a malformed
// list, as the twin does, when `clip` does not match the list's draws and meshes, or for a
// wireframe list.
Image RenderTruth(const DrawList& list, const ExactClipPositions& clip, const ExactLight* light = nullptr);
TruthImage RenderTruthSurfaces(const DrawList& list, const ExactClipPositions& clip, const ExactLight* light = nullptr);

// The framebuffer position (x, y, depth) in double of a clip-space vertex: the Vulkan viewport
// transform with the viewport covering the canvas (x = (x/w + 1)·W/2, ...), minDepth 0, maxDepth 1.
glm::dvec3 ExactFramebuffer(glm::dvec4 clip, std::uint32_t width, std::uint32_t height);

}  // namespace twinraster::truth
