#include "verify/work_estimate.hpp"

#include <glm/vec4.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace twinraster::verify {

namespace {

// Bit k set: the clip-space point is outside plane k (x < -w, x > w, y < -w, y > w, z < 0, z > w).
unsigned Outcode(const glm::dvec4& p) {
  return unsigned(p.x < -p.w) | unsigned(p.x > p.w) << 1 | unsigned(p.y < -p.w) << 2 | unsigned(p.y > p.w) << 3 |
         unsigned(p.z < 0) << 4 | unsigned(p.z > p.w) << 5;
}

// One triangle's clipped screen box, in pixels (both ends counted, as a scan of its rows would).
std::uint64_t BoxPixels(const std::array<glm::dvec4, 3>& c, std::uint32_t width, std::uint32_t height) {
  if ((Outcode(c[0]) & Outcode(c[1]) & Outcode(c[2])) != 0) return 0;  // wholly outside one plane
  double x0 = width, x1 = 0, y0 = height, y1 = 0;
  for (const glm::dvec4& p : c) {
    if (!(p.w > 0))
      return std::uint64_t{width} * height;  // crosses the eye plane: its clipped part may span the canvas
    const double x = (p.x / p.w + 1) * 0.5 * width, y = (p.y / p.w + 1) * 0.5 * height;
    x0 = std::min(x0, x), x1 = std::max(x1, x), y0 = std::min(y0, y), y1 = std::max(y1, y);
  }
  // The viewport's y flip does not change a box's area.
  const auto span = [](double lo, double hi, std::uint32_t size) {
    return std::max(0.0, std::min(std::floor(hi), size - 1.0) - std::max(std::floor(lo), 0.0) + 1);
  };
  return std::uint64_t(span(x0, x1, width) * span(y0, y1, height));
}

}  // namespace

std::uint64_t EstimatePixelTests(const DrawList& list, std::uint64_t stop_above) {
  std::uint64_t total = 0;
  std::vector<glm::dvec4> clip;
  for (const DrawCall& draw : list.draws) {
    const DrawMesh& mesh = list.meshes[draw.mesh];
    const glm::dmat4 f(draw.F);
    clip.resize(mesh.positions.size());
    for (std::size_t v = 0; v < clip.size(); ++v) clip[v] = f * glm::dvec4(glm::dvec3(mesh.positions[v]), 1.0);
    for (const auto& t : mesh.triangles) {
      total += BoxPixels({clip[t[0]], clip[t[1]], clip[t[2]]}, list.width, list.height);
      if (total > stop_above) return total;
    }
  }
  return total;
}

}  // namespace twinraster::verify
