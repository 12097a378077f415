#include "cpu/lavapipe/clipping.hpp"

#include <bit>
#include <cmath>
#include <utility>

namespace twinraster::cpu {

namespace {

// Plane vectors: distance = dot(clip, plane). Plane 4 is the Vulkan near plane z >= 0.
constexpr float kPlanes[kClipPlaneCount][4] = {
    {-1, 0, 0, 1},  // w - x >= 0
    {1, 0, 0, 1},   // x + w >= 0
    {0, -1, 0, 1},  // w - y >= 0
    {0, 1, 0, 1},   // y + w >= 0
    {0, 0, 1, 0},   // z >= 0
    {0, 0, -1, 1},  // w - z >= 0
};
// The x and y planes at the guard band (draw_pt_post_vs.c's DO_CLIP_XY_GUARD_BAND): w ± x/2 >= 0.
constexpr float kGuardBandPlanes[4][4] = {
    {-0.5f, 0, 0, 1},
    {0.5f, 0, 0, 1},
    {0, -0.5f, 0, 1},
    {0, 0.5f, 0, 1},
};

// Linear interpolation from `base` toward `other`, per component: base + t * (other - base).
template <int N>
glm::vec<N, float> Lerp(float t, const glm::vec<N, float>& base, const glm::vec<N, float>& other) {
  glm::vec<N, float> r(0.0f);
  for (int k = 0; k < N; ++k) r[k] = base[k] + t * (other[k] - base[k]);
  return r;
}

// The new vertex at t from `base` toward `other`: position and colour alike.
void Interpolate(float t, const ClipVertex& base, const ClipVertex& other, ClipVertex& v) {
  v.clip = Lerp(t, base.clip, other.clip);
  v.colour = Lerp(t, base.colour, other.colour);
}

}  // namespace

unsigned Outcode(const glm::vec4& clip) {
  unsigned code = 0;
  if (clip.x > clip.w) code |= kOutsideXMax;
  if (0.0f > clip.x + clip.w) code |= kOutsideXMin;
  if (clip.y > clip.w) code |= kOutsideYMax;
  if (0.0f > clip.y + clip.w) code |= kOutsideYMin;
  if (0.0f > clip.z) code |= kOutsideZMin;
  if (clip.z > clip.w) code |= kOutsideZMax;
  return code;
}

float PlaneDistance(const glm::vec4& clip, int plane, bool guard_band_xy) {
  const float* p = guard_band_xy && plane < 4 ? kGuardBandPlanes[plane] : kPlanes[plane];
  return ((clip.x * p[0] + clip.y * p[1]) + clip.z * p[2]) + clip.w * p[3];
}

ClipVertex IntersectEdge(const ClipVertex& prev, float d_prev, const ClipVertex& cur, float d_cur,
                         const ViewportState& vp) {
  // The same divisions, with the same signs, as the draw module: t is the base vertex's distance
  // over the difference of the distances, the base being the vertex nearer the plane.
  const float denom = d_cur - d_prev;
  ClipVertex v;
  if (d_cur < 0.0f) {  // leaving: prev inside, cur outside
    if (-d_cur < d_prev) {
      Interpolate(d_cur / denom, cur, prev, v);  // the outside vertex is nearer
    } else {
      Interpolate(-d_prev / denom, prev, cur, v);
    }
  } else {  // entering: prev outside, cur inside
    if (-d_prev < d_cur) {
      Interpolate(-d_prev / denom, prev, cur, v);  // the outside vertex is nearer
    } else {
      Interpolate(d_cur / denom, cur, prev, v);
    }
  }
  v.window = ViewportTransformClipped(vp, v.clip);
  return v;
}

void ClipTriangle(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, unsigned clipmask,
                  const ViewportState& vp, ClippedPolygon& out, bool guard_band_xy) {
  constexpr int kCapacity = kMaxClippedVertices + 1;
  ClipVertex buffer_a[kCapacity];
  ClipVertex buffer_b[kCapacity];
  ClipVertex* in = buffer_a;
  ClipVertex* next = buffer_b;
  in[0] = a;
  in[1] = b;
  in[2] = c;
  int n = 3;
  int created = 0;  // new vertices so far; the draw module has room for kMaxClippedVertices + 1
  out.count = 0;

  while (clipmask != 0 && n >= 3) {
    const int plane = std::countr_zero(clipmask);
    clipmask &= ~(1u << plane);

    float d_prev = PlaneDistance(in[0].clip, plane, guard_band_xy);
    if (!std::isfinite(d_prev) || n >= kMaxClippedVertices) return;
    in[n] = in[0];  // close the loop without rotating the vertices

    int count = 0;
    for (int i = 1; i <= n; ++i) {
      const float d = PlaneDistance(in[i].clip, plane, guard_band_xy);
      if (!std::isfinite(d)) return;
      bool crosses;
      if (d_prev >= 0.0f) {  // keep the previous vertex: it is inside (or on the plane)
        if (count >= kMaxClippedVertices) return;
        next[count++] = in[i - 1];
        crosses = d < 0.0f;
      } else {
        crosses = !(d < 0.0f);
      }
      if (crosses) {
        if (created >= kMaxClippedVertices + 1 || count >= kMaxClippedVertices) return;
        ++created;
        next[count] = IntersectEdge(in[i - 1], d_prev, in[i], d, vp);
        next[count++].edge = d < 0.0f ? vp.rules.wireframe_clip_edges : in[i - 1].edge;
      }
      d_prev = d;
    }
    std::swap(in, next);
    n = count;
  }

  if (n < 3) return;
  for (int i = 0; i < n; ++i) out.v[static_cast<std::size_t>(i)] = in[i];
  out.count = n;
}

}  // namespace twinraster::cpu
