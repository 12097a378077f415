// Primitive assembly for the verifier: every primitive a draw makes, in draw order and bounded (the
// triangles of each clipped fan, or in wireframe each clipped polygon's edges). It does not judge
// pixels, keep depths or share anything between threads (verifier.cpp and pass1_ring.hpp do).
#pragma once

#include "chain/draw_list.hpp"
#include "verify/bounded_geometry.hpp"
#include "verify/coverage_shapes.hpp"
#include "verify/frame_shared.hpp"
#include "verify/mesh_neighbours.hpp"
#include "verify/verification.hpp"

#include <glm/vec2.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <optional>
#include <vector>

namespace twinraster::verify {

// A draw's vertices bounded in clip space and, for those inside the view volume, mapped to the
// framebuffer once for all the triangles that share them.
struct DrawGeometry {
  std::vector<BoundedVertex> clip;
  std::vector<WindowVertex> window;
  std::vector<char> inside;
};

// A draw prepared once for all the bands: its geometry, and the extent of the rows its triangles
// may reach (none when unknown: the draw reaches every band).
struct PreparedDraw {
  DrawGeometry g;
  std::optional<std::array<double, 2>> rows;
};

// A draw that reaches a band: the union of its primitives' boxes there and of their depth ranges
// (NaN when any range is), so that one test can skip a draw only when it would skip each of them.
struct DrawReach {
  std::size_t draw = 0;
  PixelBox box;
  std::array<double, 2> range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void Add(const PixelBox& b, std::array<double, 2> r) {
    box = box.Empty() ? b
                      : PixelBox{std::min(box.x0, b.x0), std::min(box.y0, b.y0), std::max(box.x1, b.x1),
                                 std::max(box.y1, b.y1)};
    if (std::isnan(r[0]) || std::isnan(r[1]) || std::isnan(range[0])) {
      range = {std::nan(""), std::nan("")};
      return;
    }
    range = {std::min(range[0], r[0]), std::max(range[1], r[1])};
  }
  bool Contains(int x, int y) const { return x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1; }
};

// The primitives of a frame's draws as a device with `options`' rasterization assembles them, one
// draw at a time, each bounded by how far a conformant implementation may move it.
class Primitives {
 public:
  Primitives(const FrameShared& shared, const DrawList& list, const VerifyOptions& options)
      : list_(list),
        shared_(shared),
        subpixel_bits_(options.subpixel_bits),
        line_rules_(options.strict_lines ? LineRules::kStrict : LineRules::kNotStrict) {}

  // visit(shape, flat colour, triangle index, whether unclipped) for each primitive of draw d, with
  // a TriangleShape or a LineShape; `colours` asks for lit corner colours (pass 2 only).
  template <class Visit>
  void ForEachInDraw(std::size_t d, bool colours, DrawGeometry& g, Visit&& visit) const {
    Prepare(d, g);
    VisitDraw(d, colours, g, visit);
  }

  // ForEachInDraw once Prepare(d, g) has run.
  template <class Visit>
  void VisitDraw(std::size_t d, bool colours, const DrawGeometry& g, Visit&& visit) const;

  // A draw's vertices bounded and, where inside the view volume, mapped to the framebuffer.
  void Prepare(std::size_t d, DrawGeometry& g) const;
  // Draw d prepared for every band's pass 1: its geometry and the rows its triangles may reach.
  void PrepareForPass1(std::size_t d, PreparedDraw& p) const;

 private:
  template <class Visit>
  void VisitLines(const WindowPolygon& polygon, Rgb8 colour, std::size_t t, Visit&& visit) const {
    for (std::size_t i = 0; i < polygon.size; ++i) {
      visit(LineShape(polygon.v[i], polygon.v[(i + 1) % polygon.size], polygon.edge_from_clipping[i], line_rules_,
                      list_.width, list_.height),
            colour, t, false);
    }
  }
  template <class Visit>
  void VisitClippedWireframe(const std::array<BoundedVertex, 3>& v, bool inside, Rgb8 colour, std::size_t t,
                             Visit&& visit) const;
  std::optional<std::array<double, 2>> RowExtent(const DrawGeometry& g) const;

  const DrawList& list_;
  const FrameShared& shared_;
  int subpixel_bits_;
  LineRules line_rules_;
};

// The triangles across a triangle's three edges, made when first needed.
using AcrossEdges = std::array<std::optional<TriangleShape>, 3>;

// The depth range pass 1 may take as certain at a centre `p` that unclipped triangle t of `mesh`
// (`shape`) does not certainly cover: a centre inside the triangle but within reach of one edge it
// shares with another triangle of the mesh is covered by one of the two whichever way the edge
// moves (the vertices are the same for both, and the spec's tie rule leaves no gap between them),
// with the farther of the two depths. None anywhere else (outside: the neighbour decides from its
// side; near a corner; across a border or a fold).
std::optional<std::array<double, 2>> DepthAcrossSharedEdge(const TriangleShape& shape, glm::dvec2 p,
                                                           const DrawMesh& mesh,
                                                           const std::vector<std::array<Neighbour, 3>>& neighbours,
                                                           std::size_t t, const DrawGeometry& g, AcrossEdges& across);

template <class Visit>
void Primitives::VisitDraw(std::size_t d, bool colours, const DrawGeometry& g, Visit&& visit) const {
  const DrawMesh& mesh = list_.meshes[list_.draws[d].mesh];
  const bool lit = mesh.smooth() && shared_.lit();  // lit or vertex-coloured: corner colours vary
  FrameShared::Corners scratch;
  const FrameShared::Corners& corner = lit && colours ? shared_.CornerColours(d, scratch) : scratch;
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const auto& tri = mesh.triangles[t];
    const bool inside = g.inside[tri[0]] && g.inside[tri[1]] && g.inside[tri[2]];
    if (!list_.wireframe && inside) {
      std::array<WindowVertex, 3> v{g.window[tri[0]], g.window[tri[1]], g.window[tri[2]]};
      if (!corner.empty()) {
        for (std::size_t k = 0; k < 3; ++k) v[k].colour = corner[t][k];
      }
      visit(TriangleShape(v[0], v[1], v[2], lit), mesh.colours[t], t, true);
      continue;
    }
    std::array<BoundedVertex, 3> v{g.clip[tri[0]], g.clip[tri[1]], g.clip[tri[2]]};
    if (!corner.empty()) {
      for (std::size_t k = 0; k < 3; ++k) v[k].colour = corner[t][k];
    }
    if (list_.wireframe) {
      VisitClippedWireframe(v, inside, mesh.colours[t], t, visit);
      continue;
    }
    const WindowPolygon polygon = ClipToWindow(v[0], v[1], v[2], list_.width, list_.height, subpixel_bits_);
    for (std::size_t i = 2; i < polygon.size; ++i) {
      visit(TriangleShape(polygon.v[0], polygon.v[i - 1], polygon.v[i], lit), mesh.colours[t], t, false);
    }
  }
}

// A wireframe triangle's edges, clipped by depth only (see ClipVolume::kDepth); `inside` when all
// three vertices are inside the view volume.
template <class Visit>
void Primitives::VisitClippedWireframe(const std::array<BoundedVertex, 3>& v, bool inside, Rgb8 colour, std::size_t t,
                                       Visit&& visit) const {
  const WindowPolygon polygon =
      ClipToWindow(v[0], v[1], v[2], list_.width, list_.height, subpixel_bits_, ClipVolume::kDepth);
  VisitLines(polygon, colour, t, visit);
  if (inside) return;  // no clipping, no new edge
  // An implementation that clips by the whole view volume may also draw the edges that clipping
  // makes along the canvas's border: they may show, never must.
  const WindowPolygon view = ClipToWindow(v[0], v[1], v[2], list_.width, list_.height, subpixel_bits_);
  for (std::size_t i = 0; i < view.size; ++i) {
    if (view.edge_from_clipping[i]) {
      visit(LineShape(view.v[i], view.v[(i + 1) % view.size], true, line_rules_, list_.width, list_.height), colour, t,
            false);
    }
  }
}

}  // namespace twinraster::verify
