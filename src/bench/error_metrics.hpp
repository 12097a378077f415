// How wrong a method is, measured against the double-precision ground truth: the largest distance
// a vertex lands from where it should in the framebuffer, and the pixels that differ.
#pragma once

#include "bench/vertex_methods.hpp"
#include "image/image.hpp"
#include "truth/truth_renderer.hpp"

#include <cstdint>

namespace twinraster {

// Max over every vertex the truth has inside the clip volume (only those reach the framebuffer as
// themselves) of the distance in pixels between its framebuffer position from `clip` and the
// truth's. Returns 0 when no vertex is inside.
double VertexErrorPixels(const ClipPositions& clip, const ExactClipPositions& truth, std::uint32_t width,
                         std::uint32_t height);

}  // namespace twinraster
