#include "truth/truth_raster.hpp"

#include "truth/exact_orientation.hpp"

#include <algorithm>
#include <cmath>
#include <utility>

namespace twinraster::truth {

namespace {

glm::dvec2 Xy(const glm::dvec3& v) { return {v.x, v.y}; }

bool IsFinite(const glm::dvec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Inclusive pixel range whose centres (p + 0.5) may lie in [lo, hi], within [0, size).
// Rounding of lo - 0.5 can only widen the range, and the edge test decides exactly.
std::pair<int, int> CentreRange(double lo, double hi, std::uint32_t size) {
  const double first = std::max(0.0, std::ceil(lo - 0.5));
  const double last = std::min(static_cast<double>(size) - 1.0, std::floor(hi - 0.5));
  if (!(first <= last)) return {0, -1};
  return {static_cast<int>(first), static_cast<int>(last)};
}

// One edge ready for testing: endpoints and its tie rule.
struct Edge {
  glm::dvec2 a, b;
  bool tie_inside = false;
};

// Coverage of one pixel centre. On success `weights` gets the three edge functions opposite
// vertices 0, 1, 2: up to the common factor 2·area, the centre's barycentric coordinates.
bool CoversCentre(const std::array<Edge, 3>& edges, glm::dvec2 centre, std::array<double, 3>& weights) {
  for (std::size_t i = 0; i < 3; ++i) {
    const EdgeValue e = EvaluateEdge(edges[i].a, edges[i].b, centre);
    if (e.sign < 0 || (e.sign == 0 && !edges[i].tie_inside)) return false;
    weights[(i + 2) % 3] = e.value;  // edge i -> i+1 is opposite vertex i+2
  }
  return true;
}

// Window z is affine in window x, y: at a covered centre it is the barycentric blend of the
// vertices' z. The weights are >= 0 with a positive sum, so the blend stays within the vertices'
// range; it is clamped to the depth range [0, 1] as the rasterizer does.
double InterpolateDepth(const std::array<glm::dvec3, 3>& v, const std::array<double, 3>& weights) {
  const double sum = weights[0] + weights[1] + weights[2];
  const double z = (weights[0] * v[0].z + weights[1] * v[1].z + weights[2] * v[2].z) / sum;
  return std::clamp(z, 0.0, 1.0);
}

// A lit colour at a covered centre: perspective-correct, Σ b_i c_i / w_i over Σ b_i / w_i, with
// the window-space weights b_i; then to UNORM8 as round(clamp(c, 0, 1) · 255), to nearest with
// ties to even (nearbyint in the default rounding mode), no float anywhere. The tie rule shows
// only where c · 255 is k + 1/2 exactly in double; there float renderers may round either way.
Rgb8 InterpolateColour(const WindowTriangle& t, const std::array<double, 3>& weights) {
  glm::dvec3 sum(0.0);
  double norm = 0;
  for (std::size_t k = 0; k < 3; ++k) {
    sum += (*t.colours)[k] * (weights[k] / t.w[k]);
    norm += weights[k] / t.w[k];
  }
  const auto unorm = [](double c) {
    return static_cast<std::uint8_t>(std::nearbyint(std::clamp(c, 0.0, 1.0) * 255.0));
  };
  const glm::dvec3 c = sum / norm;
  return Rgb8{unorm(c.x), unorm(c.y), unorm(c.z)};
}

void WriteFragment(TruthTarget& target, int px, int py, double z, Rgb8 colour, std::uint64_t surface) {
  const std::size_t i = target.index(px, py);
  if (!DepthPasses(z, target.depth[i], target.reversed_z)) return;
  target.depth[i] = z;
  std::uint8_t* p = &target.colour.rgba[i * 4];
  p[0] = colour.r;
  p[1] = colour.g;
  p[2] = colour.b;
  p[3] = 255;
  if (!target.surfaces.empty()) target.surfaces[i] = surface;
}

}  // namespace

TruthTarget::TruthTarget(std::uint32_t width, std::uint32_t height, Rgb8 background, bool reversed, bool keep_surfaces)
    : colour(width, height),
      depth(std::size_t{width} * height, reversed ? 0.0 : 1.0),
      reversed_z(reversed),
      surfaces(keep_surfaces ? std::size_t{width} * height : 0, 0) {
  for (std::size_t i = 0; i < depth.size(); ++i) {
    std::uint8_t* p = &colour.rgba[i * 4];
    p[0] = background.r;
    p[1] = background.g;
    p[2] = background.b;
    p[3] = 255;
  }
}

bool IsTopOrLeftEdge(glm::dvec2 a, glm::dvec2 b) {
  const bool left = a.y < b.y;
  const bool top = a.y == b.y && a.x > b.x;
  return left || top;
}

bool DepthPasses(double fragment, double stored, bool reversed_z) {
  return reversed_z ? fragment > stored : fragment < stored;
}

void DrawTriangle(TruthTarget& target, const WindowTriangle& triangle) {
  WindowTriangle t = triangle;
  std::array<glm::dvec3, 3>& v = t.v;
  if (!IsFinite(v[0]) || !IsFinite(v[1]) || !IsFinite(v[2])) return;

  // Orientation, as the twin's setup does: zero area draws nothing, negative swaps vertices 1 and 2
  // so that the inside is where all three edge functions are positive.
  const int area_sign = EvaluateEdge(Xy(v[0]), Xy(v[1]), Xy(v[2])).sign;
  if (area_sign == 0) return;
  if (area_sign < 0) {
    std::swap(v[1], v[2]);
    std::swap(t.w[1], t.w[2]);
    if (t.colours) std::swap((*t.colours)[1], (*t.colours)[2]);
  }

  std::array<Edge, 3> edges;
  for (std::size_t i = 0; i < 3; ++i) {
    const glm::dvec2 a = Xy(v[i]), b = Xy(v[(i + 1) % 3]);
    edges[i] = Edge{a, b, IsTopOrLeftEdge(a, b)};
  }

  const auto [x0, x1] =
      CentreRange(std::min({v[0].x, v[1].x, v[2].x}), std::max({v[0].x, v[1].x, v[2].x}), target.colour.width);
  const auto [y0, y1] =
      CentreRange(std::min({v[0].y, v[1].y, v[2].y}), std::max({v[0].y, v[1].y, v[2].y}), target.colour.height);
  for (int py = y0; py <= y1; ++py) {
    for (int px = x0; px <= x1; ++px) {
      const glm::dvec2 centre{px + 0.5, py + 0.5};
      std::array<double, 3> weights;
      if (!CoversCentre(edges, centre, weights)) continue;
      const Rgb8 colour = t.colours ? InterpolateColour(t, weights) : t.colour;
      WriteFragment(target, px, py, InterpolateDepth(v, weights), colour, t.surface);
    }
  }
}

}  // namespace twinraster::truth
