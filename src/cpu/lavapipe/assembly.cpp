#include "cpu/lavapipe/assembly.hpp"

#include "cpu/chunk_loop.hpp"
#include "cpu/vertex_stage.hpp"

namespace twinraster::cpu {

ShadedVertex ShadeVertex(const glm::mat4& f, const glm::vec3& position, const ViewportState& vp) {
  return ShadeClipVertex(VertexStage(f, position), vp);
}

ShadedVertex ShadeClipVertex(const glm::vec4& clip, const ViewportState& vp) {
  ShadedVertex s;
  s.v.clip = clip;
  s.v.window = ViewportTransformShader(vp, s.v.clip);  // lavapipe transforms every shader vertex
  s.outcode = Outcode(s.v.clip);
  return s;
}

namespace {

// Primitive assembly and clipping for one triangle: set_up(a, b, c) for the triangle itself, or
// for each triangle of its clipped fan, or for none.
template <class SetUp>
void AssembleFan(const ClipVertex& a, unsigned a_out, const ClipVertex& b, unsigned b_out, const ClipVertex& c,
                 unsigned c_out, const ViewportState& vp, SetUp&& set_up) {
  const unsigned any_outside = a_out | b_out | c_out;
  if (any_outside == 0) {
    set_up(a, b, c);
    return;
  }
  if ((a_out & b_out & c_out) != 0) return;  // entirely outside one plane

  ClippedPolygon polygon;
  ClipTriangle(a, b, c, any_outside, vp, polygon);
  for (int i = 2; i < polygon.count; ++i) {
    const auto& p = polygon.v;
    set_up(p[0], p[static_cast<std::size_t>(i - 1)], p[static_cast<std::size_t>(i)]);
  }
}

}  // namespace

void AssembleTriangle(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour, const ViewportState& vp,
                      const PixelRect& region, std::vector<TriangleSetup>& out) {
  // Set up in place: a copy through the stack would cost store-forwarding stalls on every field.
  AssembleFan(v[0]->v, v[0]->outcode, v[1]->v, v[1]->outcode, v[2]->v, v[2]->outcode, vp,
              [&](const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
                TriangleSetup& setup = out.emplace_back();
                setup.colour = colour;
                if (!SetUpTriangle(a.window, b.window, c.window, region, setup, vp.rules))
                  out.pop_back();
                else
                  setup.depth.fused = vp.rules.fused_multiply_add;
              });
}

void AssembleSmoothTriangle(const std::array<const ShadedVertex*, 3>& v, const std::array<glm::vec3, 3>& colours,
                            const ViewportState& vp, const PixelRect& region, std::vector<TriangleSetup>& out,
                            std::vector<ColourPlanes>& planes) {
  std::array<ClipVertex, 3> corner = {v[0]->v, v[1]->v, v[2]->v};
  for (std::size_t k = 0; k < 3; ++k) corner[k].colour = colours[k];
  AssembleFan(corner[0], v[0]->outcode, corner[1], v[1]->outcode, corner[2], v[2]->outcode, vp,
              [&](const ClipVertex& a, const ClipVertex& b, const ClipVertex& c) {
                TriangleSetup& setup = out.emplace_back();
                if (!SetUpTriangle(a.window, b.window, c.window, region, setup, vp.rules)) {
                  out.pop_back();
                  return;
                }
                setup.smooth = true;
                setup.depth.fused = vp.rules.fused_multiply_add;
                setup.colour = static_cast<std::uint32_t>(planes.size());
                // In post-swap order, like the depth plane.
                const bool fused = vp.rules.fused_multiply_add;
                planes.push_back(setup.swapped ? MakeColourPlanes(a, c, b, fused) : MakeColourPlanes(a, b, c, fused));
              });
}

void AssembleWireframe(const std::array<const ShadedVertex*, 3>& v, std::uint32_t colour, const ViewportState& vp,
                       const PixelRect& region, std::vector<LineSetup>& out) {
  const auto line = [&](const WindowPos& a, const WindowPos& b) {
    LineSetup& setup = out.emplace_back();
    setup.colour = colour;
    if (!SetUpLine(a, b, region, vp.rules, setup)) out.pop_back();
  };
  const unsigned any_outside = v[0]->outcode | v[1]->outcode | v[2]->outcode;
  const unsigned all_outside = v[0]->outcode & v[1]->outcode & v[2]->outcode;
  if (any_outside == 0) {
    line(v[2]->v.window, v[0]->v.window);
    line(v[0]->v.window, v[1]->v.window);
    line(v[1]->v.window, v[2]->v.window);
    return;
  }
  if (all_outside != 0) return;

  ClippedPolygon polygon;
  ClipTriangle(v[0]->v, v[1]->v, v[2]->v, any_outside, vp, polygon, vp.rules.wireframe_guard_band);
  const int n = polygon.count;
  const auto edge = [&](int i, int j) {
    const ClipVertex& from = polygon.v[static_cast<std::size_t>(i)];
    if (from.edge) line(from.window, polygon.v[static_cast<std::size_t>(j)].window);
  };
  if (n < 3) return;
  if (n == 3) {
    edge(2, 0);
    edge(0, 1);
    edge(1, 2);
    return;
  }
  for (int i = 0; i + 2 < n; ++i) edge(i, i + 1);
  edge(n - 1, 0);
  edge(n - 2, n - 1);
}

std::size_t LavapipeScratch::bytes() const {
  std::size_t total = vertices.capacity() * sizeof(ShadedVertex);
  for (const auto& part : triangles) total += part.capacity() * sizeof(TriangleSetup);
  for (const auto& part : colour_planes) total += part.capacity() * sizeof(ColourPlanes);
  for (const auto& part : lines) total += part.capacity() * sizeof(LineSetup);
  return total;
}

// The shared loop with lavapipe's assembly, instantiated here so that the assembly is inlined.
void ProcessGeometry(const DrawList& list, const GeometryChunk& chunk, unsigned threads, const RasterRules& rules,
                     LavapipeGeometry& scratch, const std::vector<std::vector<glm::vec4>>* clip, unsigned band_count) {
  const LavapipeAssembly assembly(list.width, list.height, rules, scratch.device);
  SetUpChunk(list, chunk, threads, rules, assembly, scratch, clip, band_count);
}

}  // namespace twinraster::cpu
