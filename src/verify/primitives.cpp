#include "verify/primitives.hpp"

namespace twinraster::verify {

void Primitives::Prepare(std::size_t d, DrawGeometry& g) const {
  const DrawCall& draw = list_.draws[d];
  BoundVertices(draw.F, list_.meshes[draw.mesh].positions, g.clip);
  g.window.resize(g.clip.size());
  g.inside.assign(g.clip.size(), 0);
  for (std::size_t i = 0; i < g.clip.size(); ++i) {
    g.inside[i] = InsideViewVolume(g.clip[i]);
    if (g.inside[i]) g.window[i] = MapToWindow(g.clip[i], list_.width, list_.height, subpixel_bits_);
  }
}

void Primitives::PrepareForPass1(std::size_t d, PreparedDraw& p) const {
  Prepare(d, p.g);
  p.rows = RowExtent(p.g);
}

// The extent in y of the rows the prepared draw's triangles may reach (a box's rows are those
// whose centres y + 0.5 lie in it): each triangle's Box lies within its draw's vertices' extent
// widened by the largest radius any of them has. None for wireframes and draws that clipping
// cuts, which are never culled by rows.
std::optional<std::array<double, 2>> Primitives::RowExtent(const DrawGeometry& g) const {
  if (list_.wireframe) return std::nullopt;
  double y0 = std::numeric_limits<double>::infinity(), y1 = -y0, error = 0;
  for (std::size_t i = 0; i < g.clip.size(); ++i) {
    if (!g.inside[i]) return std::nullopt;
    y0 = std::min(y0, g.window[i].xy.y), y1 = std::max(y1, g.window[i].xy.y);
    error = std::max(error, g.window[i].xy_error);
  }
  const double radius = std::sqrt(2.0) * error;  // as TriangleShape's, so never smaller than one
  y0 -= radius, y1 += radius;
  if (!std::isfinite(y0) || !std::isfinite(y1)) return std::nullopt;
  return std::array<double, 2>{y0, y1};
}

std::optional<std::array<double, 2>> DepthAcrossSharedEdge(const TriangleShape& shape, glm::dvec2 p,
                                                           const DrawMesh& mesh,
                                                           const std::vector<std::array<Neighbour, 3>>& neighbours,
                                                           std::size_t t, const DrawGeometry& g, AcrossEdges& across) {
  if (shape.Degenerate()) return std::nullopt;
  const std::array<double, 3> dt = shape.EdgeDistances(p);
  std::size_t near = 3;  // the one edge it lies within reach of
  for (std::size_t j = 0; j < 3; ++j) {
    if (dt[j] < 0) return std::nullopt;  // outside: the neighbour decides from its side
    if (dt[j] <= shape.EdgeRadius(int(j))) {
      if (near < 3) return std::nullopt;  // near a corner
      near = j;
    }
  }
  if (near == 3) return std::nullopt;
  const Neighbour n = neighbours[t][near];
  if (n.triangle < 0) return std::nullopt;
  const auto& nt = mesh.triangles[std::size_t(n.triangle)];
  if (!g.inside[nt[0]] || !g.inside[nt[1]] || !g.inside[nt[2]]) return std::nullopt;
  if (!across[near]) across[near].emplace(g.window[nt[0]], g.window[nt[1]], g.window[nt[2]], false);
  const TriangleShape& other = *across[near];
  if (other.Degenerate()) return std::nullopt;
  // The other triangle must lie across the shared edge, not folded over this one.
  const double r = std::max(shape.radius(), other.radius());
  if (shape.EdgeDistances(g.window[nt[std::size_t((n.edge + 2) % 3)]].xy)[near] >= -r) return std::nullopt;
  const std::array<double, 3> dn = other.EdgeDistances(p);
  for (std::size_t j = 0; j < 3; ++j) {
    if (int(j) != n.edge && dn[j] <= other.EdgeRadius(int(j))) return std::nullopt;
  }
  const std::array<double, 2> a = shape.Depth(p), b = other.Depth(p);
  return std::array<double, 2>{std::min(a[0], b[0]), std::max(a[1], b[1])};
}

}  // namespace twinraster::verify
