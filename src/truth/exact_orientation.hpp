// Edge functions of double coordinates with an exact sign, as if evaluated with infinite
// precision: ties are true zeros, and a shared edge sorts every pixel centre the same way for both
// of its triangles (no centre covered twice or missed for rounding's sake).
#pragma once

#include <glm/vec2.hpp>

namespace twinraster::truth {

// The edge function of edge a -> b at p, in the twin's convention (cpu/lavapipe/setup.hpp, window
// y down): E = (a.y - b.y)(a.x - p.x) - (a.x - b.x)(a.y - p.y). E(v0, v1, v2) is twice the signed
// area, and for a positive area all three edge functions are > 0 inside.
struct EdgeValue {
  int sign = 0;      // the exact value's sign: -1, 0 or 1
  double value = 0;  // an approximation with that same sign, for interpolation weights
};

// Exact unless a product underflows, which window coordinates (0 .. 16384) never come near.
EdgeValue EvaluateEdge(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p);

// The same value computed only with exact arithmetic (no fast path); for tests.
EdgeValue EvaluateEdgeExactly(glm::dvec2 a, glm::dvec2 b, glm::dvec2 p);

}  // namespace twinraster::truth
