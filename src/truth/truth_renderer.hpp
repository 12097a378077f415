// The ground truth: the scene's transform chain and rasterization evaluated in double precision
// with no float rounding and no subpixel snapping, the reference that defines "error".
#pragma once

#include "chain/draw_list.hpp"
#include "image/image.hpp"
#include "scene/scene.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace twinraster {

// Clip-space positions in double for one draw: clip[i] = F_double · (mesh vertex i, 1), where
// F_double is the instance's matrix composed in double and never rounded to float. One vector per
// DrawList::draws entry.
using ExactClipPositions = std::vector<std::vector<glm::dvec4>>;

// The host chain in double (SceneChain, InstanceMatrix) applied to the Scene's double vertices.
ExactClipPositions ExactClipSpace(const Scene& scene);

// The ground truth image: same topology, colours, canvas size, background and depth mode
// (DrawList::reversed_z: clear 0, GREATER; else clear 1, LESS) as `list`, but positions from
// `clip`. Clipping, viewport transform, coverage at pixel centres (top-left rule on exact ties)
// and depth all in double. Throws std::invalid_argument for a malformed list, as the twin does,
// when `clip` does not match the list's draws and meshes, or for a wireframe list.
Image RenderTruth(const DrawList& list, const ExactClipPositions& clip);

// The framebuffer position (x, y, depth) in double of a clip-space vertex: the Vulkan viewport
// transform with the viewport covering the canvas (x = (x/w + 1)·W/2, ...), minDepth 0, maxDepth 1.
glm::dvec3 ExactFramebuffer(glm::dvec4 clip, std::uint32_t width, std::uint32_t height);

}  // namespace twinraster
