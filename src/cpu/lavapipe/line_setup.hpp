// Stage 5 for wireframes (polygonMode LINE, width 1), as llvmpipe sets a line up (Mesa 22.3.6,
// lp_setup_line.c, try_setup_line, rectangular lines; docs/wireframe.md lists every rule with its
// source and the test that checks it against the installed driver):
//  - A line whose float length is 0 draws nothing.
//  - Each endpoint snaps to 1/256 pixel by llvmpipe's util_iround: round half AWAY from zero,
//    computed as a float add of ±0.5 and a truncation (triangles round half to even). From Mesa 25
//    util_iround is lrintf: half to even (RasterRules::lines_round_half_even).
//  - The line is a parallelogram around the snapped segment, half a pixel either side:
//    (tx, ty) = iround(256 · 0.5 · (-dy, dx) / |d|), corners P1 - t, P2 - t, P2 + t, P1 + t.
//    No end caps, no diamond-exit rule, no x-major/y-major choice.
//  - Its four edge functions take the triangles' form and top-left rule (MakeEdge).
//  - Depth is a plane anchored at the line's first endpoint, in float without FMA:
//    dzdx = (dz·dx)/|d|², dzdy = (dz·dy)/|d|², a0 = z1 - (dzdx·(x1 - 0.5) + dzdy·(y1 - 0.5)),
//    then evaluated per pixel exactly as for triangles (DepthAt).
#pragma once

#include "cpu/lavapipe/plane.hpp"
#include "cpu/lavapipe/setup.hpp"
#include "cpu/lavapipe/viewport.hpp"

#include <array>
#include <cstdint>

namespace twinraster::cpu {

struct LineSetup {
  std::array<EdgeFunction, 4> edges;
  PixelRect bounds;  // pixels that may be covered, inside the draw region
  DepthPlane depth;
  std::uint32_t colour = 0;
};

// The line from a to b, a first (the depth plane hangs on a). False when it covers nothing for
// sure (zero length, or its box misses `region`).
// `rules`: how endpoints round (lines_round_half_even) and how depth is evaluated (fused).
bool SetUpLine(const WindowPos& a, const WindowPos& b, const PixelRect& region, const RasterRules& rules,
               LineSetup& out);

}  // namespace twinraster::cpu
