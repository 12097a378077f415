#include "chain/explain.hpp"

#include "chain/frustum.hpp"
#include "chain/light_trace.hpp"
#include "chain/matrices.hpp"
#include "chain/normals.hpp"
#include "base/usage_error.hpp"
#include "chain/vertex_trace.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <array>
#include <cstdio>

#include <glm/mat4x4.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <vector>

namespace twinraster {

namespace {

// The instances and vertex indices the options select, checked.
struct Selection {
  std::vector<std::size_t> instances;
  std::vector<std::size_t> Vertices(const Model& model) const {
    if (vertex) return {*vertex};
    std::vector<std::size_t> all(model.vertices.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    return all;
  }
  std::optional<std::size_t> vertex;
};

Selection Select(const Scene& scene, const ExplainOptions& options) {
  Selection selection;
  if (options.instance) {
    if (*options.instance >= scene.instances.size()) {
      throw UsageError("--instance " + std::to_string(*options.instance) + ": the scene has " +
                       std::to_string(scene.instances.size()) + " instance(s)");
    }
    selection.instances = {*options.instance};
  } else {
    // A million instances would be a million traces: show the first few, and say so.
    const std::size_t shown = std::min(scene.instances.size(), kExplainedInstances);
    for (std::size_t i = 0; i < shown; ++i) selection.instances.push_back(i);
  }
  if (options.vertex) {
    for (std::size_t i : selection.instances) {
      const Model& model = scene.models[scene.instances[i].model];
      if (*options.vertex >= model.vertices.size()) {
        throw UsageError("--vertex " + std::to_string(*options.vertex) + ": instance " + std::to_string(i) +
                         " (model \"" + model.name + "\") has " + std::to_string(model.vertices.size()) +
                         " vertices");
      }
    }
    selection.vertex = options.vertex;
  }
  return selection;
}

// The grid an instance is a copy of, and its (i, j, k) there; nullptr when it was written out.
const InstanceGrid* GridOf(const Scene& scene, std::size_t instance, std::array<std::size_t, 3>& ijk) {
  for (const InstanceGrid& g : scene.grids) {
    if (instance < g.first || instance >= g.first + g.copies()) continue;
    const std::size_t n = instance - g.first;
    ijk = {n % g.count[0], n / g.count[0] % g.count[1], n / (std::size_t{g.count[0]} * g.count[1])};
    return &g;
  }
  return nullptr;
}

std::string GridText(const InstanceGrid& g) {
  char text[256];
  std::snprintf(text, sizeof text, "%u x %u x %u grid, spacing (%.6g, %.6g, %.6g)", g.count[0], g.count[1], g.count[2],
                g.spacing.x, g.spacing.y, g.spacing.z);
  return text;
}

// Everything both formats print: the chain, and per selected instance its matrices and traces.
// A traced vertex's light: which triangle corner's normal it shows (a vertex may have a
// different normal in each triangle), and the trace.
struct VertexLight {
  std::size_t triangle = 0;
  int corner = 0;
  LightTrace trace;
};

struct InstanceExplanation {
  std::size_t index = 0;
  const Model* model = nullptr;
  const Transform* transform = nullptr;
  glm::dmat4 model_matrix{1.0};  // M_Model
  glm::dmat4 f{1.0};             // F = M_Projection · M_Camera · M_Model
  std::optional<glm::dmat3> normal_matrix;  // lit models only
  std::vector<std::pair<std::size_t, VertexTrace>> vertices;
  std::vector<std::optional<VertexLight>> lights;  // lights[i] belongs to vertices[i]
};

bool IsLit(const Scene& scene, const Model& model) {
  return scene.lighting && !scene.wireframe && model.shading != Shading::kUnlit;
}

// The first triangle corner that uses vertex v, and that corner's normal.
std::optional<VertexLight> LightAt(const Scene& scene, const InstanceExplanation& x, std::size_t v,
                                   const std::vector<std::array<glm::dvec3, 3>>& normals) {
  for (std::size_t t = 0; t < x.model->triangles.size(); ++t) {
    for (int k = 0; k < 3; ++k) {
      if (x.model->triangles[t].v[static_cast<std::size_t>(k)] != v) continue;
      return VertexLight{t, k,
                         TraceLight(*scene.lighting, x.model_matrix, *x.normal_matrix, x.model->vertices[v],
                                    normals[t][static_cast<std::size_t>(k)], x.model->triangles[t].colour)};
    }
  }
  return std::nullopt;
}

struct Explanation {
  Chain chain;
  std::vector<InstanceExplanation> instances;
};

Explanation Explain(const Scene& scene, const ExplainOptions& options) {
  const Selection selection = Select(scene, options);
  Explanation e{SceneChain(scene), {}};
  std::map<const Model*, std::vector<std::array<glm::dvec3, 3>>> normals;  // per lit model, once
  for (std::size_t i : selection.instances) {
    InstanceExplanation x;
    x.index = i;
    x.model = &scene.models[scene.instances[i].model];
    x.transform = &scene.instances[i].transform;
    x.model_matrix = ModelMatrix(*x.transform);
    x.f = e.chain.projection * e.chain.camera * x.model_matrix;
    const bool lit = IsLit(scene, *x.model);
    if (lit) {
      x.normal_matrix = NormalMatrix(x.model_matrix);
      if (!normals.contains(x.model)) normals.emplace(x.model, CornerNormals(*x.model, x.model->shading));
    }
    for (std::size_t v : selection.Vertices(*x.model)) {
      x.vertices.emplace_back(v, TraceVertex(scene, e.chain, x.model_matrix, x.model->vertices[v]));
      x.lights.push_back(lit && x.normal_matrix ? LightAt(scene, x, v, normals.at(x.model)) : std::nullopt);
    }
    e.instances.push_back(std::move(x));
  }
  return e;
}

template <int N>
nlohmann::ordered_json Rows(const glm::mat<N, N, double>& m) {
  nlohmann::ordered_json rows = nlohmann::ordered_json::array();
  for (int r = 0; r < N; ++r) {
    nlohmann::ordered_json row = nlohmann::ordered_json::array();
    for (int c = 0; c < N; ++c) row.push_back(m[c][r]);
    rows.push_back(std::move(row));
  }
  return rows;
}

template <typename Vec>
nlohmann::ordered_json Array(const Vec& v) {
  nlohmann::ordered_json a = nlohmann::ordered_json::array();
  for (int i = 0; i < Vec::length(); ++i) a.push_back(v[i]);
  return a;
}

// Six significant digits, and no "-0" that would puzzle a reader.
std::string Num(double x) {
  if (x == 0) x = 0;
  char buffer[32];
  std::snprintf(buffer, sizeof buffer, "%.6g", x);
  return buffer;
}

template <typename Vec>
std::string Tuple(const Vec& v) {
  std::string s = "(";
  for (int i = 0; i < Vec::length(); ++i) s += (i ? ", " : "") + Num(v[i]);
  return s + ")";
}

// A list step's kind as the scene file writes it, and the chapter's name for its matrix.
const char* StepKind(const TransformStep& step) {
  switch (step.kind) {
    case TransformStep::Kind::kScale: return "scale";
    case TransformStep::Kind::kRotation: return "rotation";
    case TransformStep::Kind::kTranslation: return "translation";
  }
  return "?";
}
std::string StepName(const TransformStep& step) {
  switch (step.kind) {
    case TransformStep::Kind::kScale: return "I_S";
    case TransformStep::Kind::kRotation: return "I_R";
    case TransformStep::Kind::kTranslation: return "I_T";
  }
  return "?";
}

const char* ShadingName(Shading shading) {
  switch (shading) {
    case Shading::kFlat: return "flat";
    case Shading::kGouraud: return "gouraud";
    case Shading::kUnlit: break;
  }
  return "unlit";
}

void PrintLightTrace(std::ostream& out, const Scene& scene, const Model& model, const VertexLight& v) {
  const LightTrace& t = v.trace;
  out << "    normal       " << Tuple(t.object_normal) << "   as corner " << v.corner << " of triangle " << v.triangle
      << " uses it" << (model.shading == Shading::kFlat ? " (flat: the face normal; the triangle is lit at corner 0 only)" : "")
      << "\n"
      << "    world normal " << Tuple(t.world_normal) << "   = N · normal\n"
      << "    unit normal  " << Tuple(t.unit_normal) << "   renormalised (M_Model · normal would point along "
      << Tuple(t.wrong_normal) << ")\n"
      << "    light        I = ambient " << Num(t.ambient);
  for (std::size_t i = 0; i < t.terms.size(); ++i) {
    const LightTerm& term = t.terms[i];
    const bool point = scene.lighting->lights[i].kind == Light::Kind::kPoint;
    out << "\n                 + light " << i << " (" << (point ? "point" : "directional") << "): l = "
        << Tuple(term.l) << ", n·l = " << Num(term.n_dot_l) << (term.n_dot_l > 0 ? "" : " (faces away: 0)")
        << ", term " << Num(term.contribution);
  }
  const Rgb8 base = model.triangles[v.triangle].colour;
  out << "\n                 = " << Num(t.intensity) << "; colour = base (" << int{base.r} << ", " << int{base.g} << ", "
      << int{base.b} << ") / 255 · min(I, 1) = " << Tuple(t.colour) << "\n";
}

nlohmann::ordered_json LightJson(const VertexLight& v) {
  const LightTrace& t = v.trace;
  nlohmann::ordered_json terms = nlohmann::ordered_json::array();
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

// A 4x4 (or the 3x3 normal matrix) as rows, the way the chapter prints matrices.
template <int N>
void PrintMatrix(std::ostream& out, const std::string& name, const glm::mat<N, N, double>& m) {
  out << "  " << name << " =\n";
  for (int r = 0; r < N; ++r) {
    out << "    [";
    for (int c = 0; c < N; ++c) {
      char cell[32];
      std::snprintf(cell, sizeof cell, " %12s", Num(m[c][r]).c_str());
      out << cell;
    }
    out << " ]\n";
  }
}

}  // namespace

std::string ExplainText(const Scene& scene, const ExplainOptions& options) {
  const Explanation e = Explain(scene, options);
  const Chain& chain = e.chain;
  const Canvas& cv = scene.canvas;
  const Viewport& vp = scene.viewport;
  std::ostringstream out;

  out << "Scene \"" << scene.name << "\": canvas Cw x Ch = " << cv.width << " x " << cv.height
      << " px, viewport Vw x Vh = " << Num(vp.width) << " x " << Num(vp.height)
      << (vp.projection == Projection::kOrthographic ? " (orthographic: d is not used)" : " at distance d = " + Num(vp.distance))
      << ", depth near = " << Num(scene.depth.near)
      << ", far = " << Num(scene.depth.far) << (scene.depth.reversed ? " (reversed Z: near -> 1, far -> 0)" : "") << "\n"
      << "Column vectors on the right: V' = F · V, F = M_Projection · M_Camera · M_Model.\n\n";

  out << "M_Projection = CanvasToClip · ViewportToCanvas · P\n";
  if (vp.projection == Projection::kOrthographic) {
    PrintMatrix(out, "P (orthographic: x, y kept, depth row linear in z, w = 1)", OrthographicMatrix(scene.depth));
  } else {
    PrintMatrix(out, "P (perspective: x·d, y·d, depth row, w = z)", PerspectiveMatrix(vp, scene.depth));
  }
  PrintMatrix(out, "ViewportToCanvas (Cw/Vw, Ch/Vh)", ViewportToCanvas(vp, cv));
  PrintMatrix(out, "CanvasToClip (Vulkan: 2/Cw, -2/Ch)", CanvasToClip(cv));
  PrintMatrix(out, "M_Projection", chain.projection);

  out << "\nM_Camera = C_R⁻¹ · C_T⁻¹  (camera at " << Tuple(scene.camera.position) << ")\n";
  PrintMatrix(out, "C_R⁻¹ (transpose of C_R)", Rotation4(glm::transpose(scene.camera.rotation)));
  PrintMatrix(out, "C_T⁻¹", Translation(-scene.camera.position));
  PrintMatrix(out, "M_Camera", chain.camera);

  if (scene.lighting && !scene.wireframe) {
    const Lighting& lighting = *scene.lighting;
    out << "\nLighting (Computer Graphics from Scratch's diffuse model, in world space):\n"
        << "  I = ambient + sum of intensity · max(0, n·l) / (|n| |l|), l toward the light; colour = base · min(I, 1)\n"
        << "  ambient " << Num(lighting.ambient) << "\n";
    for (std::size_t i = 0; i < lighting.lights.size(); ++i) {
      const Light& light = lighting.lights[i];
      out << "  light " << i << ": "
          << (light.kind == Light::Kind::kPoint ? "point at " : "directional, l = ") << Tuple(light.vector)
          << ", intensity " << Num(light.intensity) << "\n";
    }
  } else if (scene.lighting) {
    out << "\nLighting: not used (a wireframe draws edges in the models' own colours)\n";
  }

  out << "\nInstances: " << scene.instances.size() << " in all";
  for (const InstanceGrid& g : scene.grids) {
    out << "\n  instances[" << g.written << "] of the file is a " << GridText(g) << ": " << g.copies()
        << " copies, instances " << g.first << ".." << g.first + g.copies() - 1 << ", i fastest";
  }
  if (!options.instance && e.instances.size() < scene.instances.size()) {
    out << "\n  the first " << e.instances.size() << " are traced below; pick any other with --instance I";
  }
  out << "\n";

  const char* canvas_formula = vp.projection == Projection::kOrthographic ? "(x·Cw/Vw, y·Ch/Vh), whatever z"
                                                                         : "(x·d·Cw/(z·Vw), y·d·Ch/(z·Vh))";
  for (const InstanceExplanation& x : e.instances) {
    const Transform& t = *x.transform;
    std::array<std::size_t, 3> ijk{};
    const InstanceGrid* grid = GridOf(scene, x.index, ijk);
    out << "\nInstance " << x.index << " (model \"" << x.model->name << "\"";
    if (grid) out << "; copy (" << ijk[0] << ", " << ijk[1] << ", " << ijk[2] << ") of the grid of instances[" << grid->written << "]";
    if (t.steps) {
      // Written as a list: each step's matrix in the order applied, then their product.
      const std::size_t n = t.steps->size();
      out << "): the transform is a list of " << n << " step" << (n == 1 ? "" : "s") << ", applied in the order written\n";
      std::string product;
      for (std::size_t k = 0; k < n; ++k) {
        const std::string name = StepName((*t.steps)[k]) + std::to_string(k + 1);
        PrintMatrix(out, "step " + std::to_string(k + 1) + ": " + name, StepMatrix((*t.steps)[k]));
        product = k == 0 ? name : name + " · " + product;
      }
      if (grid) {
        PrintMatrix(out, "I_T (the grid's offset, after the steps)", Translation(t.translation));
        product = "I_T · " + product;
      }
      PrintMatrix(out, "M_Model = " + (product.empty() ? std::string("I") : product), x.model_matrix);
    } else {
      out << "): M_Model = I_T · I_R · I_S\n";
      PrintMatrix(out, "I_S", Scale(t.scale));
      PrintMatrix(out, "I_R", Rotation4(t.rotation));
      PrintMatrix(out, "I_T", Translation(t.translation));
      PrintMatrix(out, "M_Model", x.model_matrix);
    }
    PrintMatrix(out, "F = M_Projection · M_Camera · M_Model", x.f);
    if (IsLit(scene, *x.model)) {
      out << "  lit, " << ShadingName(x.model->shading) << " shading\n";
      if (x.normal_matrix) PrintMatrix(out, "N = (upper 3x3 of M_Model)⁻ᵀ, the normal matrix", *x.normal_matrix);
    }

    for (std::size_t i = 0; i < x.vertices.size(); ++i) {
      const auto& [v, tr] = x.vertices[i];
      out << "  vertex " << v << (tr.inside ? "" : "  (outside the clip volume: clipped when drawn)") << "\n"
          << "    object       " << Tuple(tr.object) << "\n"
          << "    world        " << Tuple(tr.world) << "   = M_Model · V\n"
          << "    camera       " << Tuple(tr.camera) << "   = M_Camera · world\n"
          << "    clip         " << Tuple(tr.clip) << "   = M_Projection · camera\n"
          << "    ndc          " << Tuple(tr.ndc) << "   = clip.xyz / clip.w\n"
          << "    canvas       " << Tuple(tr.canvas) << "   = " << canvas_formula << ", +y up\n"
          << "    framebuffer  " << Tuple(glm::dvec2(tr.framebuffer)) << " depth " << Num(tr.framebuffer.z)
          << "   Vulkan: +y down, pixel (i, j) has its centre at (i + 0.5, j + 0.5)\n";
      if (x.lights[i]) PrintLightTrace(out, scene, *x.model, *x.lights[i]);
    }
  }
  return out.str();
}

void CheckExplainOptions(const Scene& scene, const ExplainOptions& options) { static_cast<void>(Select(scene, options)); }

nlohmann::ordered_json ExplainJson(const Scene& scene, const ExplainOptions& options) {
  const Explanation e = Explain(scene, options);
  const Chain& chain = e.chain;
  nlohmann::ordered_json out;
  out["format"] = kExplainJsonFormat;
  out["scene"] = scene.name;
  out["canvas"] = {{"width", scene.canvas.width}, {"height", scene.canvas.height}};
  const bool orthographic = scene.viewport.projection == Projection::kOrthographic;
  out["viewport"] = {{"width", scene.viewport.width}, {"height", scene.viewport.height},
                     {"distance", scene.viewport.distance},
                     {"projection", orthographic ? "orthographic" : "perspective"}};
  out["depth"] = {{"near", scene.depth.near}, {"far", scene.depth.far}, {"reversed", scene.depth.reversed}};
  out["perspective_matrix"] = orthographic ? nlohmann::ordered_json(nullptr) : Rows(PerspectiveMatrix(scene.viewport, scene.depth));
  out["orthographic_matrix"] = orthographic ? Rows(OrthographicMatrix(scene.depth)) : nlohmann::ordered_json(nullptr);
  out["viewport_to_canvas"] = Rows(ViewportToCanvas(scene.viewport, scene.canvas));
  out["canvas_to_clip"] = Rows(CanvasToClip(scene.canvas));
  out["projection_matrix"] = Rows(chain.projection);
  out["camera_matrix"] = Rows(chain.camera);
  const auto frustum_json = [](const Frustum& f) {
    const auto corners = [](const std::array<glm::dvec3, 4>& c) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const glm::dvec3& p : c) list.push_back(Array(p));
      return list;
    };
    return nlohmann::ordered_json{
        {"eye", Array(f.eye)}, {"near", corners(f.near)}, {"viewport", corners(f.viewport)}, {"far", corners(f.far)}};
  };
  out["frustum"] = {{"camera", frustum_json(CameraSpaceFrustum(scene))}, {"world", frustum_json(WorldFrustum(scene, chain))}};
  out["lighting"] = nlohmann::ordered_json(nullptr);
  if (scene.lighting && !scene.wireframe) {
    nlohmann::ordered_json lights = nlohmann::ordered_json::array();
    for (const Light& light : scene.lighting->lights) {
      const bool point = light.kind == Light::Kind::kPoint;
      lights.push_back({{"type", point ? "point" : "directional"},
                        {point ? "position" : "direction", Array(light.vector)},
                        {"intensity", light.intensity}});
    }
    out["lighting"] = {{"ambient", scene.lighting->ambient}, {"lights", lights}};
  }
  out["instance_count"] = scene.instances.size();
  out["grids"] = nlohmann::ordered_json::array();
  for (const InstanceGrid& g : scene.grids) {
    out["grids"].push_back({{"instance", g.written},
                            {"first", g.first},
                            {"count", {g.count[0], g.count[1], g.count[2]}},
                            {"spacing", Array(g.spacing)},
                            {"copies", g.copies()}});
  }
  out["instances"] = nlohmann::ordered_json::array();
  for (const InstanceExplanation& x : e.instances) {
    nlohmann::ordered_json entry;
    entry["index"] = x.index;
    entry["model"] = x.model->name;
    std::array<std::size_t, 3> ijk{};
    const InstanceGrid* grid = GridOf(scene, x.index, ijk);
    entry["grid_copy"] = grid ? nlohmann::ordered_json{{"instance", grid->written}, {"ijk", {ijk[0], ijk[1], ijk[2]}}}
                              : nlohmann::ordered_json(nullptr);
    entry["transform_steps"] = nlohmann::ordered_json(nullptr);
    if (x.transform->steps) {
      entry["transform_steps"] = nlohmann::ordered_json::array();
      for (const TransformStep& step : *x.transform->steps) {
        entry["transform_steps"].push_back({{"kind", StepKind(step)}, {"matrix", Rows(StepMatrix(step))}});
      }
    }
    entry["model_matrix"] = Rows(x.model_matrix);
    entry["mvp"] = Rows(x.f);  // F, under the name the tools expect
    entry["shading"] = IsLit(scene, *x.model) ? ShadingName(x.model->shading) : "unlit";
    entry["normal_matrix"] = x.normal_matrix ? Rows(*x.normal_matrix) : nlohmann::ordered_json(nullptr);
    entry["vertices"] = nlohmann::ordered_json::array();
    for (std::size_t i = 0; i < x.vertices.size(); ++i) {
      const auto& [v, tr] = x.vertices[i];
      entry["vertices"].push_back({{"index", v},
                                   {"object", Array(tr.object)},
                                   {"world", Array(tr.world)},
                                   {"camera", Array(tr.camera)},
                                   {"clip", Array(tr.clip)},
                                   {"ndc", Array(tr.ndc)},
                                   {"canvas", Array(tr.canvas)},
                                   {"framebuffer", Array(tr.framebuffer)},
                                   {"inside_clip_volume", tr.inside},
                                   {"light", x.lights[i] ? LightJson(*x.lights[i]) : nlohmann::ordered_json(nullptr)}});
    }
    out["instances"].push_back(std::move(entry));
  }
  return out;
}

}  // namespace twinraster
