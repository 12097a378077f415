#include "truth/truth_renderer.hpp"

#include "chain/light_trace.hpp"
#include "chain/matrices.hpp"
#include "chain/normals.hpp"
#include "truth/truth_clipping.hpp"
#include "truth/truth_raster.hpp"

#include <stdexcept>
#include <string>
#include <utility>

namespace twinraster::truth {

namespace {

// The renderers' checks (ValidateDrawList), plus that `clip` has one position per mesh vertex of
// every draw.
void ValidateInputs(const DrawList& list, const ExactClipPositions& clip, const ExactLight* light) {
  ValidateDrawList(list);
  if (list.lighting && light == nullptr)
    throw std::invalid_argument("the list is lit, but the truth was given no light");
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
void DrawClipTriangle(TruthTarget& target, const glm::dvec4& a, const glm::dvec4& b, const glm::dvec4& c, Rgb8 colour,
                      std::uint64_t surface) {
  const ClipPolygon polygon = ClipToViewVolume(a, b, c);
  std::vector<glm::dvec3> window;
  window.reserve(polygon.size());
  for (const glm::dvec4& p : polygon) {
    window.push_back(ExactFramebuffer(p, target.colour.width, target.colour.height));
  }
  for (std::size_t i = 2; i < window.size(); ++i) {
    WindowTriangle t;
    t.v = {window[0], window[i - 1], window[i]};
    t.colour = colour;
    t.surface = surface;
    DrawTriangle(target, t);
  }
}

// The same for a lit triangle: the corner colours are clipped along with the positions.
void DrawLitTriangle(TruthTarget& target, const std::array<LitVertex, 3>& v, std::uint64_t surface) {
  const LitPolygon polygon = ClipToViewVolume(v[0], v[1], v[2]);
  std::vector<glm::dvec3> window;
  window.reserve(polygon.size());
  for (const LitVertex& p : polygon) {
    window.push_back(ExactFramebuffer(p.clip, target.colour.width, target.colour.height));
  }
  for (std::size_t i = 2; i < window.size(); ++i) {
    const std::size_t k[3] = {0, i - 1, i};
    WindowTriangle t;
    t.v = {window[k[0]], window[k[1]], window[k[2]]};
    t.colours = std::array<glm::dvec3, 3>{polygon[k[0]].colour, polygon[k[1]].colour, polygon[k[2]].colour};
    t.w = {polygon[k[0]].clip.w, polygon[k[1]].clip.w, polygon[k[2]].clip.w};
    t.surface = surface;
    DrawTriangle(target, t);
  }
}

TruthImage Render(const DrawList& list, const ExactClipPositions& clip, const ExactLight* light, bool surfaces) {
  ValidateInputs(list, clip, light);
  TruthTarget target(list.width, list.height, list.background, list.reversed_z, surfaces);
  // Draws in list order, triangles in index order, a clipped triangle's fan in fan order.
  std::uint64_t first_triangle = 0;  // of draw d, counting every draw's
  for (std::size_t d = 0; d < list.draws.size(); ++d) {
    const DrawMesh& mesh = list.meshes[list.draws[d].mesh];
    const std::vector<glm::dvec4>& positions = clip[d];
    const std::uint64_t first_surface = first_triangle + 1;
    first_triangle += mesh.triangles.size();
    if (mesh.smooth() && light == nullptr)
      throw std::invalid_argument("draw " + std::to_string(d) +
                                  " has vertex colours, but the truth was given no light");
    const std::vector<std::array<glm::dvec3, 3>> colours =
        mesh.smooth() ? light->CornerColours(d) : std::vector<std::array<glm::dvec3, 3>>{};
    if (mesh.smooth() && colours.size() != mesh.triangles.size()) {
      throw std::invalid_argument("draw " + std::to_string(d) + " is lit, but the truth's light does not light it");
    }
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      const std::uint64_t surface = first_surface + t;
      if (colours.empty()) {
        DrawClipTriangle(target, positions[tri[0]], positions[tri[1]], positions[tri[2]], mesh.colours[t], surface);
      } else {
        DrawLitTriangle(target,
                        {LitVertex{positions[tri[0]], colours[t][0]}, LitVertex{positions[tri[1]], colours[t][1]},
                         LitVertex{positions[tri[2]], colours[t][2]}},
                        surface);
      }
    }
  }
  return {std::move(target.colour), std::move(target.surfaces)};
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

ExactLight::ExactLight(const Scene& scene) : scene_(&scene), normals_(scene.models.size()) {
  if (!scene.lighting || scene.wireframe) return;
  for (std::size_t m = 0; m < scene.models.size(); ++m) {
    if (scene.models[m].shading != Shading::kUnlit)
      normals_[m] = CornerNormals(scene.models[m], scene.models[m].shading);
  }
}

namespace {

// An unlit vertex-coloured model's corners: each vertex's colour, k / 255.
std::vector<std::array<glm::dvec3, 3>> UnlitVertexColours(const Model& model) {
  const auto at = [&](std::uint32_t v) {
    return glm::dvec3(model.vertex_colours[v].r, model.vertex_colours[v].g, model.vertex_colours[v].b) / 255.0;
  };
  std::vector<std::array<glm::dvec3, 3>> colours(model.triangles.size());
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    const auto& v = model.triangles[t].v;
    colours[t] = {at(v[0]), at(v[1]), at(v[2])};
  }
  return colours;
}

}  // namespace

std::vector<std::array<glm::dvec3, 3>> ExactLight::CornerColours(std::size_t instance) const {
  const Scene& scene = *scene_;
  if (instance >= scene.instances.size()) throw std::invalid_argument("no instance " + std::to_string(instance));
  const Model& model = scene.models[scene.instances[instance].model];
  const std::vector<std::array<glm::dvec3, 3>>& normals = normals_[scene.instances[instance].model];
  const bool vertex_colours = !model.vertex_colours.empty() && !scene.wireframe;
  if (normals.empty() && !model.triangles.empty())
    return vertex_colours ? UnlitVertexColours(model) : std::vector<std::array<glm::dvec3, 3>>{};
  const glm::dmat4 m = ModelMatrix(scene.instances[instance].transform);
  const std::optional<glm::dmat3> n = NormalMatrix(m);
  if (!n) throw std::invalid_argument("instance " + std::to_string(instance) + " of a lit model has a zero scale");
  std::vector<std::array<glm::dvec3, 3>> colours(model.triangles.size());
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    const Triangle& tri = model.triangles[t];
    const auto at = [&](std::size_t k) {
      const Rgb8 base = vertex_colours ? model.vertex_colours[tri.v[k]] : tri.colour;
      return TraceLight(*scene.lighting, m, *n, model.vertices[tri.v[k]], normals[t][k], base).colour;
    };
    if (model.shading == Shading::kFlat) {
      const glm::dvec3 c = at(0);  // lit once, at the provoking vertex
      colours[t] = {c, c, c};
    } else {
      colours[t] = {at(0), at(1), at(2)};
    }
  }
  return colours;
}

Image RenderTruth(const DrawList& list, const ExactClipPositions& clip, const ExactLight* light) {
  return Render(list, clip, light, false).image;
}

TruthImage RenderTruthSurfaces(const DrawList& list, const ExactClipPositions& clip, const ExactLight* light) {
  return Render(list, clip, light, true);
}

}  // namespace twinraster::truth
