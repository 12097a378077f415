#include "cpu/swiftshader/assembly.hpp"

#include "cpu/chunk_loop.hpp"
#include "cpu/swiftshader/clipping.hpp"
#include "cpu/swiftshader/planes.hpp"

#include <cmath>

namespace twinraster::cpu {

namespace {

// The outline of a triangle: its snapped vertices, or the clipped polygon snapped again. False
// when nothing is left to draw.
bool TriangleOutline(const OutlineTriangle& v, const SnapViewport& vp, std::array<SnappedPoint, kMaxOutlinePoints>& p,
                     int& count) {
  const unsigned all = v[0]->outcode & v[1]->outcode & v[2]->outcode;
  const unsigned any = v[0]->outcode | v[1]->outcode | v[2]->outcode;
  if (all != kClipFinite) return false;  // a coordinate not finite, or every vertex outside one plane
  if (any == kClipFinite) {
    for (std::size_t k = 0; k < 3; ++k) p[k] = {v[k]->x, v[k]->y};
    count = 3;
    return true;
  }
  ClipSpacePolygon polygon;
  polygon.v = {v[0]->clip, v[1]->clip, v[2]->clip};
  polygon.count = 3;
  if (!ClipPolygon(polygon, any)) return false;
  for (int i = 0; i < polygon.count; ++i) {
    p[static_cast<std::size_t>(i)] = SnapPolygonVertex(polygon.v[static_cast<std::size_t>(i)], vp);
  }
  count = polygon.count;
  return true;
}

// Appends one set-up with these points, if it covers some row; returns it, or null.
OutlineSetup* Append(const SnappedPoint* p, int count, bool d, const SnapViewport& vp, OutlineOutput& out) {
  PixelRect bounds;
  if (!OutlineBounds(p, count, vp.width, vp.height, bounds)) return nullptr;
  OutlineSetup& setup = out.setups.emplace_back();
  setup.first = static_cast<std::uint32_t>(out.points.size());
  setup.count = static_cast<std::uint8_t>(count);
  setup.d = d;
  setup.bounds = bounds;
  out.points.insert(out.points.end(), p, p + count);
  return &setup;
}

// Set-up of a filled triangle's coverage and depth plane; `order` is the vertex order the planes
// were built in (PlaneOrder), for the colour planes of a smooth one.
OutlineSetup* SetUpTriangle(const OutlineTriangle& v, const SnapViewport& vp, OutlineOutput& out,
                            std::array<std::size_t, 3>& order) {
  std::array<SnappedPoint, kMaxOutlinePoints> p;
  int count = 0;
  if (!TriangleOutline(v, vp, p, count)) return nullptr;
  OutlineSetup* setup = Append(p.data(), count, OutlineWinding(*v[0], *v[1], *v[2]), vp, out);
  if (setup == nullptr) return nullptr;
  order = PlaneOrder(v);
  setup->depth = TriangleDepthPlane(*v[order[0]], *v[order[1]], *v[order[2]]);
  return setup;
}

// One wireframe line a -> b: a parallelogram half a pixel either side of the segment, without end
// caps, offset in clip space at each end in proportion to its w.
void AssembleLine(const SnappedVertex& a, const SnappedVertex& b, std::uint32_t colour, const SnapViewport& vp,
                  OutlineOutput& out) {
  const glm::vec4 &p0 = a.clip, &p1 = b.clip;
  if (p0.w <= 0 && p1.w <= 0) return;
  const float half_width = vp.wxf * (1.0f / kOutlineOne), half_height = vp.hxf * (1.0f / kOutlineOne);
  float dx = half_width * (p1.x / p1.w - p0.x / p0.w);
  float dy = half_height * (p1.y / p1.w - p0.y / p0.w);
  if (dx == 0 && dy == 0) return;
  constexpr float kLineWidth = 1.0f;
  const float scale = kLineWidth * 0.5f / std::sqrt(dx * dx + dy * dy);
  dx = dx * scale;
  dy = dy * scale;
  const float dx0h = dx * p0.w / half_height, dy0w = dy * p0.w / half_width;
  const float dx1h = dx * p1.w / half_height, dy1w = dy * p1.w / half_width;
  ClipSpacePolygon quad;
  quad.v = {p0, p1, p1, p0};
  quad.count = 4;
  quad.v[0].x += -dy0w, quad.v[0].y += dx0h;
  quad.v[1].x += -dy1w, quad.v[1].y += dx1h;
  quad.v[2].x += dy1w, quad.v[2].y += -dx1h;
  quad.v[3].x += dy0w, quad.v[3].y += -dx0h;
  if (!ClipPolygon(quad, kClipFrustum)) return;
  std::array<SnappedPoint, kMaxOutlinePoints> p;
  for (int i = 0; i < quad.count; ++i)
    p[static_cast<std::size_t>(i)] = SnapPolygonVertex(quad.v[static_cast<std::size_t>(i)], vp);
  OutlineSetup* setup = Append(p.data(), quad.count, true, vp, out);
  if (setup == nullptr) return;
  setup->depth = LineDepthPlane(a, b);
  setup->colour = colour;
}

}  // namespace

void AssembleOutlineTriangle(const OutlineTriangle& v, std::uint32_t colour, const SnapViewport& vp,
                             OutlineOutput out) {
  std::array<std::size_t, 3> k;
  OutlineSetup* setup = SetUpTriangle(v, vp, out, k);
  if (setup != nullptr) setup->colour = colour;
}

void AssembleOutlineSmooth(const OutlineTriangle& v, const std::array<glm::vec3, 3>& colours, const SnapViewport& vp,
                           OutlineOutput out) {
  std::array<std::size_t, 3> k;
  OutlineSetup* setup = SetUpTriangle(v, vp, out, k);
  if (setup == nullptr) return;
  setup->smooth = true;
  setup->colour = static_cast<std::uint32_t>(out.planes.size());
  out.planes.push_back(
      TriangleColourPlanes(*v[k[0]], *v[k[1]], *v[k[2]], {colours[k[0]], colours[k[1]], colours[k[2]]}));
}

void AssembleOutlineWireframe(const OutlineTriangle& v, std::uint32_t colour, const SnapViewport& vp,
                              OutlineOutput out) {
  AssembleLine(*v[0], *v[1], colour, vp, out);
  AssembleLine(*v[1], *v[2], colour, vp, out);
  AssembleLine(*v[2], *v[0], colour, vp, out);
}

std::size_t SwiftShaderScratch::bytes() const {
  std::size_t total = vertices.capacity() * sizeof(SnappedVertex);
  for (const auto& part : outlines) total += part.capacity() * sizeof(OutlineSetup);
  for (const auto& part : outline_points) total += part.capacity() * sizeof(SnappedPoint);
  for (const auto& part : outline_planes) total += part.capacity() * sizeof(AnchoredColourPlanes);
  return total;
}

// The shared loop with SwiftShader's assembly, instantiated here so that the assembly is inlined.
void ProcessGeometry(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                     SwiftShaderGeometry& scratch, const std::vector<std::vector<glm::vec4>>* clip,
                     unsigned band_count) {
  const SwiftShaderAssembly assembly(list.width, list.height, scratch.device);
  SetUpChunk(list, chunk, threads, rules, assembly, scratch, clip, band_count);
}

}  // namespace twinraster::cpu
