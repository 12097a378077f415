#include "bench/error_metrics.hpp"

#include "chain/vertex_trace.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace twinraster::bench {

double VertexErrorPixels(const cpu::ClipPositions& clip, const truth::ExactClipPositions& exact_clip,
                         std::uint32_t width, std::uint32_t height) {
  double worst = 0;
  for (std::size_t d = 0; d < exact_clip.size(); ++d) {
    for (std::size_t v = 0; v < exact_clip[d].size(); ++v) {
      if (!InsideClipVolume(exact_clip[d][v])) continue;
      // The method's float position, carried through the viewport transform in double so that
      // only the method's own error is measured.
      const glm::dvec3 exact = truth::ExactFramebuffer(exact_clip[d][v], width, height);
      const glm::dvec3 approx = truth::ExactFramebuffer(glm::dvec4(clip[d][v]), width, height);
      worst = std::max(worst, glm::length(glm::dvec2(approx) - glm::dvec2(exact)));
    }
  }
  return worst;
}

ColourError SameSurfaceColourError(const Image& image, const Image& surfaces, const truth::TruthImage& exact) {
  ColourError error;
  if (image.width != exact.image.width || image.height != exact.image.height || surfaces.width != image.width ||
      surfaces.height != image.height || exact.surfaces.size() != std::size_t{image.width} * image.height) {
    return error;
  }
  for (std::size_t p = 0; p < exact.surfaces.size(); ++p) {
    const std::size_t i = 4 * p;
    const std::uint64_t shown = std::uint64_t{surfaces.rgba[i]} | std::uint64_t{surfaces.rgba[i + 1]} << 8 |
                                std::uint64_t{surfaces.rgba[i + 2]} << 16;
    if (exact.surfaces[p] == 0 || shown != exact.surfaces[p]) continue;
    for (std::size_t c = 0; c < 3; ++c) {
      error.max_channel = std::max(error.max_channel, std::abs(int{image.rgba[i + c]} - int{exact.image.rgba[i + c]}));
    }
    ++error.pixels;
  }
  return error;
}

std::optional<DrawList> SurfaceList(const DrawList& list) {
  DrawList ids;
  ids.width = list.width;
  ids.height = list.height;
  ids.background = Rgb8{0, 0, 0};  // surface 0
  ids.reversed_z = list.reversed_z;
  std::uint64_t next = 1;
  for (const DrawCall& draw : list.draws) {
    const DrawMesh& mesh = list.meshes[draw.mesh];
    if (next + mesh.triangles.size() > (std::uint64_t{1} << 24)) return std::nullopt;
    DrawMesh copy;
    copy.positions = mesh.positions;
    copy.triangles = mesh.triangles;
    copy.colours.reserve(mesh.triangles.size());
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t, ++next) {
      copy.colours.push_back(Rgb8{static_cast<std::uint8_t>(next), static_cast<std::uint8_t>(next >> 8),
                                  static_cast<std::uint8_t>(next >> 16)});
    }
    ids.draws.push_back(DrawCall{static_cast<std::uint32_t>(ids.meshes.size()), draw.F});
    ids.meshes.push_back(std::move(copy));
  }
  return ids;
}

}  // namespace twinraster::bench
