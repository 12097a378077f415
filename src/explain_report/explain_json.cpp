#include "explain_report/explain_json.hpp"

#include "scene/model_reader.hpp"

#include <nlohmann/json.hpp>

#include <cmath>

namespace twinraster::explain_report {

namespace {

using Json = nlohmann::ordered_json;

// A matrix as rows, the way the chapter prints it.
template <int N>
Json Rows(const glm::mat<N, N, double>& m) {
  Json rows = Json::array();
  for (int r = 0; r < N; ++r) {
    Json row = Json::array();
    for (int c = 0; c < N; ++c) row.push_back(m[c][r]);
    rows.push_back(std::move(row));
  }
  return rows;
}

template <typename Vec>
Json Array(const Vec& v) {
  Json a = Json::array();
  for (int i = 0; i < Vec::length(); ++i) a.push_back(v[i]);
  return a;
}

const char* StepKind(TransformStep::Kind kind) {
  switch (kind) {
    case TransformStep::Kind::kScale: return "scale";
    case TransformStep::Kind::kRotation: return "rotation";
    case TransformStep::Kind::kTranslation: return "translation";
    case TransformStep::Kind::kMatrix: return "matrix";
  }
  return "?";
}

Json FrustumJson(const Frustum& f) {
  const auto corners = [](const std::array<glm::dvec3, 4>& c) {
    Json list = Json::array();
    for (const glm::dvec3& p : c) list.push_back(Array(p));
    return list;
  };
  return Json{
      {"eye", Array(f.eye)}, {"near", corners(f.near)}, {"viewport", corners(f.viewport)}, {"far", corners(f.far)}};
}

Json LightingJson(const Explanation& e) {
  if (!e.lighting_used) return Json(nullptr);
  Json lights = Json::array();
  for (const Light& light : e.scene->lighting->lights) {
    const bool point = light.kind == Light::Kind::kPoint;
    lights.push_back({{"type", point ? "point" : "directional"},
                      {point ? "position" : "direction", Array(light.vector)},
                      {"intensity", light.intensity}});
  }
  return {{"ambient", e.scene->lighting->ambient}, {"lights", lights}};
}

Json GridsJson(const Scene& scene) {
  Json grids = Json::array();
  for (const InstanceGrid& g : scene.grids) {
    grids.push_back({{"instance", g.written},
                     {"first", g.first},
                     {"count", {g.count[0], g.count[1], g.count[2]}},
                     {"spacing", Array(g.spacing)},
                     {"copies", g.copies()}});
  }
  return grids;
}

Json LightJson(const VertexLight& v) {
  const LightTrace& t = v.trace;
  Json terms = Json::array();
  for (const LightTerm& term : t.terms) {
    terms.push_back({{"l", Array(term.l)}, {"n_dot_l", term.n_dot_l}, {"contribution", term.contribution}});
  }
  return {{"triangle", v.triangle},
          {"corner", v.corner},
          {"normal", Array(t.object_normal)},
          {"world_normal", Array(t.world_normal)},
          {"unit_normal", Array(t.unit_normal)},
          {"normal_by_model_matrix", Array(t.wrong_normal)},
          {"ambient", t.ambient},
          {"terms", terms},
          {"intensity", t.intensity},
          {"colour", Array(t.colour)}};
}

Json VertexJson(const TracedVertex& v) {
  const VertexTrace& tr = v.trace;
  return {{"index", v.index},
          {"object", Array(tr.object)},
          {"world", Array(tr.world)},
          {"camera", Array(tr.camera)},
          {"clip", Array(tr.clip)},
          {"ndc", Array(tr.ndc)},
          {"canvas", Array(tr.canvas)},
          {"framebuffer", Array(tr.framebuffer)},
          {"inside_clip_volume", tr.inside},
          {"light", v.light ? LightJson(*v.light) : Json(nullptr)}};
}

Json InstanceJson(const InstanceExplanation& x) {
  Json entry;
  entry["index"] = x.index;
  entry["model"] = x.model->name;
  entry["grid_copy"] = x.grid_copy ? Json{{"instance", x.grid_copy->grid->written},
                                          {"ijk", {x.grid_copy->ijk[0], x.grid_copy->ijk[1], x.grid_copy->ijk[2]}}}
                                   : Json(nullptr);
  entry["transform_steps"] = Json(nullptr);
  if (x.steps) {
    entry["transform_steps"] = Json::array();
    for (const StepExplanation& step : *x.steps) {
      entry["transform_steps"].push_back(
          {{"kind", StepKind(step.kind)}, {"matrix", Rows(step.matrix)}, {"label", step.label}});
    }
  }
  entry["model_matrix"] = Rows(x.model_matrix);
  entry["mvp"] = Rows(x.f);  // F, under the key the explain schema names (docs/schemas/explain.schema.json)
  entry["shading"] = x.lit ? ShadingName(x.model->shading) : "unlit";
  entry["normal_matrix"] = x.normal_matrix ? Rows(*x.normal_matrix) : Json(nullptr);
  entry["vertices"] = Json::array();
  for (const TracedVertex& v : x.vertices) entry["vertices"].push_back(VertexJson(v));
  return entry;
}

}  // namespace

Json ExplainJson(const Explanation& e) {
  const Scene& scene = *e.scene;
  const bool orthographic = scene.viewport.projection == Projection::kOrthographic;
  Json out;
  out["format"] = kExplainJsonFormat;
  out["scene"] = scene.name;
  out["canvas"] = {{"width", scene.canvas.width}, {"height", scene.canvas.height}};
  out["viewport"] = {{"width", scene.viewport.width},
                     {"height", scene.viewport.height},
                     {"distance", scene.viewport.distance},
                     {"projection", orthographic ? "orthographic" : "perspective"}};
  // JSON has no infinity: an infinite far plane (a glTF camera without zfar) is null.
  const Json far = std::isinf(scene.depth.far) ? Json(nullptr) : Json(scene.depth.far);
  out["depth"] = {{"near", scene.depth.near}, {"far", far}, {"reversed", scene.depth.reversed}};
  out["perspective_matrix"] = orthographic ? Json(nullptr) : Rows(e.p);
  out["orthographic_matrix"] = orthographic ? Rows(e.p) : Json(nullptr);
  out["viewport_to_canvas"] = Rows(e.viewport_to_canvas);
  out["canvas_to_clip"] = Rows(e.canvas_to_clip);
  out["projection_matrix"] = Rows(e.chain.projection);
  out["camera_matrix"] = Rows(e.chain.camera);
  out["frustum"] = {{"camera", FrustumJson(e.camera_frustum)}, {"world", FrustumJson(e.world_frustum)}};
  out["lighting"] = LightingJson(e);
  out["instance_count"] = scene.instances.size();
  out["grids"] = GridsJson(scene);
  out["instances"] = Json::array();
  for (const InstanceExplanation& x : e.instances) out["instances"].push_back(InstanceJson(x));
  return out;
}

Json FollowedVertexJson(const InstanceExplanation& instance) {
  const bool has_vertex = instance.traced < instance.vertices.size();
  return {{"instance", instance.index},
          {"vertex", has_vertex ? VertexJson(instance.vertices[instance.traced]) : Json(nullptr)}};
}

}  // namespace twinraster::explain_report
