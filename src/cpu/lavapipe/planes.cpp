#include "cpu/lavapipe/planes.hpp"

namespace twinraster::cpu {

ColourPlanes MakeColourPlanes(const ClipVertex& v0, const ClipVertex& v1, const ClipVertex& v2, bool fused) {
  // The draw module stores 1/w (a float divide) as the position's w; setup multiplies each
  // perspective-interpolated input by it.
  const float oow0 = 1.0f / v0.clip.w, oow1 = 1.0f / v1.clip.w, oow2 = 1.0f / v2.clip.w;
  ColourPlanes p;
  for (int k = 0; k < 3; ++k) {
    p.colour_oow[static_cast<std::size_t>(k)] =
        MakePlane(v0.window, v1.window, v2.window, v0.colour[k] * oow0, v1.colour[k] * oow1, v2.colour[k] * oow2);
  }
  p.oow = MakePlane(v0.window, v1.window, v2.window, oow0, oow1, oow2);
  p.oow.fused = fused;
  for (DepthPlane& plane : p.colour_oow) plane.fused = fused;
  return p;
}

}  // namespace twinraster::cpu
