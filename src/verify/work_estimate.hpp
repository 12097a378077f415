// The verifier's work before it starts: how many pixel tests its passes may make, estimated in one
// pass over the draw list, so that a scene with too much overdraw is found inconclusive in
// seconds instead of judged for hours. It does not judge any pixel (verifier.hpp does).
#pragma once

#include "chain/draw_list.hpp"

#include <cstdint>

namespace twinraster::verify {

// The sum over every draw's triangles of their screen bounding boxes, clipped to the canvas, in
// pixels: what pass 1 and pass 2 scan at most, before their fast paths skip hidden tiles. A
// triangle wholly outside one clip plane counts 0; one crossing the eye plane (w <= 0 at some
// corner, so it has no finite box) counts the whole canvas. Stops counting once past `stop_above`,
// so the estimate costs one transform per vertex and a few operations per triangle, no more.
std::uint64_t EstimatePixelTests(const DrawList& list, std::uint64_t stop_above);

}  // namespace twinraster::verify
