#include "cpu/lavapipe/plane.hpp"

namespace twinraster::cpu {

DepthPlane MakeDepthPlane(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2) {
  return MakePlane(v0, v1, v2, v0.z, v1.z, v2.z);
}

DepthPlane MakePlane(const WindowPos& v0, const WindowPos& v1, const WindowPos& v2, float a0, float a1, float a2) {
  // Twice the signed area in float, and its reciprocal.
  const float dx01 = v0.x - v1.x, dy01 = v0.y - v1.y;
  const float dx20 = v2.x - v0.x, dy20 = v2.y - v0.y;
  const float e = dx01 * dy20;
  const float f = dy01 * dx20;
  const float ooa = 1.0f / (e - f);
  const float dx20_ooa = dx20 * ooa, dy20_ooa = dy20 * ooa;
  const float dx01_ooa = dx01 * ooa, dy01_ooa = dy01 * ooa;

  // Gradients, then the value at the origin, going back from v0 (at pixel centre offsets).
  const float dz01 = a0 - a1;
  const float dz20 = a2 - a0;
  DepthPlane p;
  p.dzdx = dz01 * dy20_ooa - dz20 * dy01_ooa;
  p.dzdy = dz20 * dx01_ooa - dz01 * dx20_ooa;
  const float x0_center = v0.x - 0.5f;
  const float y0_center = v0.y - 0.5f;
  p.a0 = a0 - (p.dzdx * x0_center + p.dzdy * y0_center);
  return p;
}

}  // namespace twinraster::cpu
