// Stage 5 as SwiftShader rasterizes (docs/swiftshader-rules.md, "Triangle setup and coverage"): a
// polygon's outline is scan-converted row by row. Each non-horizontal edge, walked in the polygon's
// order (reversed when the winding `d` is 0), gives row py the value
//   ceil(x_edge(16 py) / 16), clamped to [0, width],
// exactly, for the rows with y_top <= 16 py < y_bottom; an edge running upwards writes the row's
// right end, one running downwards its left end, later edges overwriting earlier ones. Pixel px is
// covered when left <= px < right: the top-left rule at 4 subpixel bits. The winding comes from a
// float area, so a sliver whose float area has the wrong sign gets its ends swapped and draws
// nothing, as on SwiftShader. The twin computes each end exactly in 64-bit integers, where
// SwiftShader steps a 32-bit DDA: the two agree while an edge spans less than 2^27 sixteenths of a
// pixel, which clipping ensures for every point but one snapped from a NaN (INT32_MIN). It does not
// clip or snap (clipping.hpp, viewport.hpp) or set up (setup.hpp), and lavapipe's edge functions
// are cpu/lavapipe/setup.hpp's.
#pragma once

#include "cpu/packets.hpp"
#include "cpu/swiftshader/viewport.hpp"

#include <cstdint>

namespace twinraster::cpu {

// The covered span of row py.
Span OutlineSpan(const SnappedPoint* points, int count, bool d, int width, int py);

}  // namespace twinraster::cpu
