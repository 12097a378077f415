#include "cpu/swiftshader/clipping.hpp"

#include "cpu/swiftshader/viewport.hpp"

namespace twinraster::cpu {

namespace {

// The point where edge inside -> outside crosses the plane, every component from the same formula.
glm::vec4 Crossing(const glm::vec4& inside, const glm::vec4& outside, float d_in, float d_out) {
  const float scale = 1.0f / (d_out - d_in);
  glm::vec4 p;
  for (int k = 0; k < 4; ++k) p[k] = (d_out * inside[k] - d_in * outside[k]) * scale;
  return p;
}

template <class Distance>
void ClipAgainst(ClipSpacePolygon& polygon, Distance&& distance) {
  ClipSpacePolygon out;
  // A convex polygon gains at most one vertex per plane. One made slightly concave by rounding could
  // gain more: the buffer is never overrun, the polygon is cut short instead.
  const auto keep = [&](const glm::vec4& v) {
    if (out.count < kMaxOutlinePoints) out.v[static_cast<std::size_t>(out.count++)] = v;
  };
  const int n = polygon.count;
  for (int i = 0; i < n; ++i) {
    const glm::vec4& vi = polygon.v[static_cast<std::size_t>(i)];
    const glm::vec4& vj = polygon.v[static_cast<std::size_t>(i + 1 == n ? 0 : i + 1)];
    const float di = distance(vi), dj = distance(vj);
    if (di >= 0) {
      keep(vi);
      if (dj < 0) keep(Crossing(vi, vj, di, dj));
    } else if (dj > 0) {
      keep(Crossing(vj, vi, dj, di));
    }
  }
  polygon = out;
}

}  // namespace

bool ClipPolygon(ClipSpacePolygon& polygon, unsigned planes) {
  const auto clip = [&](unsigned bit, auto&& distance) {
    if ((planes & bit) != 0 && polygon.count >= 3) ClipAgainst(polygon, distance);
  };
  clip(kClipNear, [](const glm::vec4& v) { return v.z; });
  clip(kClipFar, [](const glm::vec4& v) { return v.w - v.z; });
  clip(kClipLeft, [](const glm::vec4& v) { return v.w + v.x; });
  clip(kClipRight, [](const glm::vec4& v) { return v.w - v.x; });
  clip(kClipTop, [](const glm::vec4& v) { return v.w - v.y; });
  clip(kClipBottom, [](const glm::vec4& v) { return v.w + v.y; });
  return polygon.count >= 3;
}

}  // namespace twinraster::cpu
