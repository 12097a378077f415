// How wrong a method is, measured against the double-precision ground truth: the largest distance
// a vertex lands from where it should in the framebuffer, the pixels that differ, and for a lit
// scene how far its colours are from the truth's.
#pragma once

#include "bench/vertex_methods.hpp"
#include "image/image.hpp"
#include "truth/truth_renderer.hpp"

#include <cstdint>
#include <optional>

namespace twinraster::bench {

// Max over every vertex the truth has inside the clip volume (only those reach the framebuffer as
// themselves) of the distance in pixels between its framebuffer position from `clip` and the
// truth's. Returns 0 when no vertex is inside.
double VertexErrorPixels(const cpu::ClipPositions& clip, const truth::ExactClipPositions& exact_clip,
                         std::uint32_t width, std::uint32_t height);

// A lit image's colours against the truth's, triangle by triangle: over the pixels where the
// image shows the same triangle as the truth, the largest channel difference, 0..255. Which
// triangle the image shows comes from `surfaces`, the same geometry rendered the same way from
// SurfaceList (coverage and depth do not depend on colour), so edges that the two rasterize
// differently are left out rather than counted as colour.
struct ColourError {
  int max_channel = 0;
  std::uint64_t pixels = 0;  // pixels compared
};
ColourError SameSurfaceColourError(const Image& image, const Image& surfaces, const truth::TruthImage& exact);

// The list unlit, each draw with its own copy of its mesh whose triangles are coloured by their
// number (TruthImage::surfaces' numbering) as 24-bit RGB, red lowest. nullopt when the list has
// more than 2^24 - 1 triangles in all.
std::optional<DrawList> SurfaceList(const DrawList& list);

}  // namespace twinraster::bench
