#include "bench/error_metrics.hpp"

#include "chain/vertex_trace.hpp"

#include <glm/geometric.hpp>

#include <algorithm>

namespace twinraster {

double VertexErrorPixels(const ClipPositions& clip, const ExactClipPositions& truth, std::uint32_t width,
                         std::uint32_t height) {
  double worst = 0;
  for (std::size_t d = 0; d < truth.size(); ++d) {
    for (std::size_t v = 0; v < truth[d].size(); ++v) {
      if (!InsideClipVolume(truth[d][v])) continue;
      // The method's float position, carried through the viewport transform in double so that
      // only the method's own error is measured.
      const glm::dvec3 exact = ExactFramebuffer(truth[d][v], width, height);
      const glm::dvec3 approx = ExactFramebuffer(glm::dvec4(clip[d][v]), width, height);
      worst = std::max(worst, glm::length(glm::dvec2(approx) - glm::dvec2(exact)));
    }
  }
  return worst;
}

}  // namespace twinraster
