#include "truth/truth_renderer.hpp"

#include "chain/matrices.hpp"
#include "truth/truth_clipping.hpp"
#include "truth/truth_raster.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace twinraster {

namespace {

// The renderers' checks (ValidateDrawList), plus that `clip` has one position per mesh vertex of
// every draw.
void ValidateInputs(const DrawList& list, const ExactClipPositions& clip) {
  ValidateDrawList(list);
  if (list.wireframe) {
    // Lines have no exact pixel set to compare with: their width is a rasterization rule.
    throw std::invalid_argument("the truth draws filled triangles only, and this list is a wireframe");
  }
  if (clip.size() != list.draws.size()) {
    throw std::invalid_argument("clip positions for " + std::to_string(clip.size()) + " draws, but the list has " +
                                std::to_string(list.draws.size()));
  }
  for (std::size_t d = 0; d < list.draws.size(); ++d) {
    const std::size_t vertices = list.meshes[list.draws[d].mesh].positions.size();
    if (clip[d].size() != vertices) {
      throw std::invalid_argument("draw " + std::to_string(d) + " has " + std::to_string(clip[d].size()) +
                                  " clip positions for " + std::to_string(vertices) + " vertices");
    }
  }
}

// Clipping, then the viewport transform of the polygon's vertices, then the fan, drawn in order.
void DrawClipTriangle(truth::TruthTarget& target, const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c,
                      Rgb8 colour) {
  const truth::ClipPolygon polygon = truth::ClipToViewVolume(a, b, c);
  std::vector<glm::dvec3> window;
  window.reserve(polygon.size());
  for (const glm::dvec4& p : polygon) {
    window.push_back(ExactFramebuffer(p, target.colour.width, target.colour.height));
  }
  for (std::size_t i = 2; i < window.size(); ++i) {
    truth::DrawTriangle(target, truth::WindowTriangle{{window[0], window[i - 1], window[i]}, colour});
  }
}

}  // namespace

ExactClipPositions ExactClipSpace(const Scene& scene) {
  const Chain chain = SceneChain(scene);
  ExactClipPositions clip;
  clip.reserve(scene.instances.size());
  for (const Instance& instance : scene.instances) {
    if (instance.model >= scene.models.size()) {
      throw std::invalid_argument("instance uses model " + std::to_string(instance.model) + " of " +
                                  std::to_string(scene.models.size()));
    }
    const glm::dmat4 f = InstanceMatrix(chain, instance.transform);  // never rounded to float
    std::vector<glm::dvec4>& positions = clip.emplace_back();
    for (const glm::dvec3& v : scene.models[instance.model].vertices) positions.push_back(f * glm::dvec4(v, 1.0));
  }
  return clip;
}

glm::dvec3 ExactFramebuffer(glm::dvec4 clip, std::uint32_t width, std::uint32_t height) {
  const double w = static_cast<double>(width), h = static_cast<double>(height);
  // Viewport (0, 0, W, H), depth range [0, 1]: clip z/w already lies in [0, 1] (Vulkan).
  return {(clip.x / clip.w + 1.0) * w / 2.0, (clip.y / clip.w + 1.0) * h / 2.0, clip.z / clip.w};
}

Image RenderTruth(const DrawList& list, const ExactClipPositions& clip) {
  ValidateInputs(list, clip);
  truth::TruthTarget target(list.width, list.height, list.background, list.reversed_z);
  // Draws in list order, triangles in index order, a clipped triangle's fan in fan order.
  for (std::size_t d = 0; d < list.draws.size(); ++d) {
    const DrawMesh& mesh = list.meshes[list.draws[d].mesh];
    const std::vector<glm::dvec4>& positions = clip[d];
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      DrawClipTriangle(target, positions[tri[0]], positions[tri[1]], positions[tri[2]], mesh.colours[t]);
    }
  }
  return std::move(target.colour);
}

}  // namespace twinraster
