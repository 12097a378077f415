#include "chain/explanation.hpp"

#include "base/counted.hpp"
#include "base/usage_error.hpp"
#include "chain/normals.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace twinraster {

namespace {

// The instances the options select, checked, with the vertex asked for checked against each.
std::vector<std::size_t> SelectInstances(const Scene& scene, const ExplainOptions& options) {
  std::vector<std::size_t> selected;
  if (options.instance) {
    if (*options.instance >= scene.instances.size()) {
      throw UsageError("--instance " + std::to_string(*options.instance) + ": the scene has " +
                       Counted(scene.instances.size(), "instance") + ValidIndices(scene.instances.size()));
    }
    selected = {*options.instance};
  } else {
    // A million instances would be a million traces: explain the first few; the writers say so.
    const std::size_t shown = std::min(scene.instances.size(), kExplainedInstances);
    for (std::size_t i = 0; i < shown; ++i) selected.push_back(i);
  }
  if (!options.vertex) return selected;
  for (std::size_t i : selected) {
    const Model& model = scene.models[scene.instances[i].model];
    if (*options.vertex >= model.vertices.size()) {
      throw UsageError("--vertex " + std::to_string(*options.vertex) + ": instance " + std::to_string(i) +
                       " (model \"" + model.name + "\") has " + Counted(model.vertices.size(), "vertex", "vertices") +
                       ValidIndices(model.vertices.size()));
    }
  }
  return selected;
}

std::optional<GridCopy> GridCopyOf(const Scene& scene, std::size_t instance) {
  for (const InstanceGrid& g : scene.grids) {
    if (instance < g.first || instance >= g.first + g.copies()) continue;
    const std::size_t n = instance - g.first;
    return GridCopy{&g, {n % g.count[0], n / g.count[0] % g.count[1], n / (std::size_t{g.count[0]} * g.count[1])}};
  }
  return std::nullopt;
}

// M_Model's factors as the transform was written.
void Factor(const Transform& t, InstanceExplanation& x) {
  x.translation = Translation(t.translation);
  if (t.steps) {
    x.steps.emplace();
    for (const TransformStep& step : *t.steps) x.steps->push_back({step.kind, StepMatrix(step), step.label});
  } else {
    x.scale = Scale(t.scale);
    x.rotation = Rotation4(t.rotation);
  }
}

}  // namespace

Rgb8 CornerBase(const Model& model, std::size_t triangle, std::size_t corner) {
  const Triangle& t = model.triangles[triangle];
  return model.vertex_colours.empty() ? t.colour : model.vertex_colours[t.v[corner]];
}

namespace {

// The first triangle corner that uses vertex v, and its light; none when no triangle uses v.
std::optional<VertexLight> LightAt(const Scene& scene, const InstanceExplanation& x, std::size_t v,
                                   const std::vector<std::array<glm::dvec3, 3>>& normals) {
  const Model& model = *x.model;
  for (std::size_t t = 0; t < model.triangles.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      if (model.triangles[t].v[k] != v) continue;
      return VertexLight{t, static_cast<int>(k),
                         TraceLight(*scene.lighting, x.model_matrix, *x.normal_matrix, model.vertices[v], normals[t][k],
                                    CornerBase(model, t, k))};
    }
  }
  return std::nullopt;
}

// The vertices the options ask for, and which of them is followed. Without a vertex asked for,
// the followed one is the first the camera sees, so that a learner's trace lands on the canvas.
void TraceVertices(const Scene& scene, const Chain& chain, const ExplainOptions& options, InstanceExplanation& x) {
  const Model& model = *x.model;
  const auto trace = [&](std::size_t v) {
    return TracedVertex{v, TraceVertex(scene, chain, x.model_matrix, model.vertices[v]), std::nullopt};
  };
  if (options.vertices == ExplainVertices::kAll) {
    for (std::size_t v = 0; v < model.vertices.size(); ++v) x.vertices.push_back(trace(v));
    const auto inside =
        std::find_if(x.vertices.begin(), x.vertices.end(), [](const TracedVertex& t) { return t.trace.inside; });
    if (options.vertex) {
      x.traced = *options.vertex;
    } else if (inside != x.vertices.end()) {
      x.traced = static_cast<std::size_t>(inside - x.vertices.begin());
    }
    return;
  }
  if (options.vertex) {
    x.vertices.push_back(trace(*options.vertex));
    return;
  }
  for (std::size_t v = 0; v < model.vertices.size(); ++v) {
    TracedVertex t = trace(v);
    if (!t.trace.inside) continue;
    x.vertices.push_back(std::move(t));
    return;
  }
  if (!model.vertices.empty()) x.vertices.push_back(trace(0));
}

}  // namespace

Explanation Explain(const Scene& scene, const ExplainOptions& options) {
  const std::vector<std::size_t> selected = SelectInstances(scene, options);
  Explanation e;
  e.scene = &scene;
  e.options = options;
  e.chain = SceneChain(scene);
  e.p = ProjectionP(scene.viewport, scene.depth);
  e.viewport_to_canvas = ViewportToCanvas(scene.viewport, scene.canvas);
  e.canvas_to_clip = CanvasToClip(scene.canvas);
  e.camera_rotation_inverse = Rotation4(glm::transpose(scene.camera.rotation));
  e.camera_translation_inverse = Translation(-scene.camera.position);
  e.camera_frustum = CameraSpaceFrustum(scene);
  e.world_frustum = WorldFrustum(scene, e.chain);
  e.lighting_used = scene.lighting && !scene.wireframe;
  std::map<const Model*, std::vector<std::array<glm::dvec3, 3>>> normals;  // per lit model, once
  for (std::size_t i : selected) {
    InstanceExplanation x;
    x.index = i;
    x.model = &scene.models[scene.instances[i].model];
    x.grid_copy = GridCopyOf(scene, i);
    Factor(scene.instances[i].transform, x);
    x.model_matrix = ModelMatrix(scene.instances[i].transform);
    x.f = e.chain.projection * e.chain.camera * x.model_matrix;
    x.lit = e.lighting_used && x.model->shading != Shading::kUnlit;
    if (x.lit) x.normal_matrix = NormalMatrix(x.model_matrix);
    TraceVertices(scene, e.chain, options, x);
    if (x.normal_matrix) {
      auto [at, added] = normals.try_emplace(x.model);
      if (added) at->second = CornerNormals(*x.model, x.model->shading);
      for (TracedVertex& v : x.vertices) v.light = LightAt(scene, x, v.index, at->second);
    }
    e.instances.push_back(std::move(x));
  }
  return e;
}

}  // namespace twinraster
