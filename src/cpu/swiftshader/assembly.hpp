// Primitive assembly as SwiftShader does it, from shaded vertices to OutlineSetups
// (docs/swiftshader-rules.md): a triangle is dropped when a coordinate is not finite or all three
// vertices are outside one plane, clipped when any is outside, and set up as one polygon with the
// original triangle's planes. In polygon mode LINE each triangle gives three lines, v0 -> v1,
// v1 -> v2, v2 -> v0, each a 1-pixel-wide quad built in clip space, clipped and set up alone; the
// triangle itself is never clipped. SwiftShaderAssembly is what the shared loop
// (cpu/chunk_assembly.hpp) calls, SwiftShaderScratch what it fills and the renderer draws. It does
// not rasterize (coverage.hpp) and does not follow lavapipe's assembly (cpu/lavapipe/assembly.hpp).
#pragma once

#include "cpu/packets.hpp"
#include "cpu/swiftshader/coverage.hpp"
#include "cpu/swiftshader/plane.hpp"
#include "cpu/swiftshader/setup.hpp"
#include "cpu/swiftshader/viewport.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace twinraster::cpu {

// Where assembly appends: the set-ups, their points, and the colour planes of smooth ones.
struct OutlineOutput {
  std::vector<OutlineSetup>& setups;
  std::vector<SnappedPoint>& points;
  std::vector<AnchoredColourPlanes>& planes;
};

using OutlineTriangle = std::array<const SnappedVertex*, 3>;

// A filled triangle of one colour (unlit, or flat: the lit colour of its first vertex).
void AssembleOutlineTriangle(const OutlineTriangle& v, std::uint32_t colour, const SnapViewport& vp, OutlineOutput out);

// A Gouraud triangle whose vertices have the given colours.
void AssembleOutlineSmooth(const OutlineTriangle& v, const std::array<glm::vec3, 3>& colours, const SnapViewport& vp,
                           OutlineOutput out);

// A wireframe triangle's three lines.
void AssembleOutlineWireframe(const OutlineTriangle& v, std::uint32_t colour, const SnapViewport& vp,
                              OutlineOutput out);

// What SwiftShader's assembly sets a chunk up into, per part (one per setup thread), filled or
// wireframe alike: the set-ups, their points and the colour planes of the smooth ones. Kept from
// one chunk and one render to the next: fresh memory costs a page fault per 4 KiB.
struct SwiftShaderScratch {
  std::vector<SnappedVertex> vertices;
  std::vector<std::vector<OutlineSetup>> outlines;
  std::vector<std::vector<SnappedPoint>> outline_points;
  std::vector<std::vector<AnchoredColourPlanes>> outline_planes;

  // Empties the parts and reserves room for `share(part)` input triangles in each.
  template <class Share>
  void Reserve(unsigned parts, bool /*wireframe*/, Share&& share) {
    const auto fit = [&](auto& per_part) {
      per_part.resize(parts);
      for (auto& part : per_part) part.clear();
    };
    fit(outlines);
    fit(outline_points);
    fit(outline_planes);
    for (unsigned part = 0; part < parts; ++part) {
      const std::size_t n = share(part);
      outlines[part].reserve(n + 16);
      outline_points[part].reserve(3 * n + 16);
    }
  }
  // Bins part p's set-ups into bins[band] (the indices of those whose box touches the band).
  void Bin(unsigned part, std::vector<std::vector<std::uint32_t>>& bins) const { BinPrimitives(outlines[part], bins); }
  // draw(parts, rows) with this chunk's set-ups and how to cover their rows (OutlineSpan on their
  // points, inside `width`).
  template <class DrawFn>
  void Draw(int width, DrawFn&& draw) const {
    draw(outlines, Rows{*this, width});
  }
  // The colour planes of part p's smooth set-up whose colour is `index`.
  const AnchoredColourPlanes& SmoothPlanes(std::size_t part, std::uint32_t index) const {
    return outline_planes[part][index];
  }
  std::size_t bytes() const;

 private:
  struct Rows {
    const SwiftShaderScratch& scratch;
    int width;
    template <class OnSpan>
    void operator()(std::size_t p, const OutlineSetup& o, int row_begin, int row_end, OnSpan&& on_span) const {
      const SnappedPoint* points = scratch.outline_points[p].data() + o.first;
      for (int py = row_begin; py < row_end; ++py) {
        const Span span = OutlineSpan(points, o.count, o.d, width, py);
        if (span.begin < span.end) on_span(py, span);
      }
    }
  };
};

// SwiftShader's assembly as the shared loop calls it: per vertex a snapped position, per triangle
// one polygon, or three lines, each an OutlineSetup.
class SwiftShaderAssembly {
 public:
  using Vertex = SnappedVertex;
  using Scratch = SwiftShaderScratch;

  SwiftShaderAssembly(std::uint32_t width, std::uint32_t height, SwiftShaderScratch& scratch)
      : vp_(MakeSnapViewport(width, height)), scratch_(scratch) {}

  Vertex Shade(const glm::vec4& clip) const { return SnapShaderVertex(clip, vp_); }
  void Flat(const OutlineTriangle& v, std::uint32_t colour, unsigned part) const {
    AssembleOutlineTriangle(v, colour, vp_, Out(part));
  }
  void Smooth(const OutlineTriangle& v, const std::array<glm::vec3, 3>& colours, unsigned part) const {
    AssembleOutlineSmooth(v, colours, vp_, Out(part));
  }
  void Wireframe(const OutlineTriangle& v, std::uint32_t colour, unsigned part) const {
    AssembleOutlineWireframe(v, colour, vp_, Out(part));
  }

 private:
  OutlineOutput Out(unsigned part) const {
    return {scratch_.outlines[part], scratch_.outline_points[part], scratch_.outline_planes[part]};
  }
  SnapViewport vp_;
  SwiftShaderScratch& scratch_;
};

}  // namespace twinraster::cpu
