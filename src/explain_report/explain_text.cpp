#include "explain_report/explain_text.hpp"

#include "base/counted.hpp"
#include "scene/model_reader.hpp"

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <sstream>

namespace twinraster::explain_report {

namespace {

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

// The chapter's name for a list step's matrix.
std::string StepName(TransformStep::Kind kind) {
  switch (kind) {
    case TransformStep::Kind::kScale: return "I_S";
    case TransformStep::Kind::kRotation: return "I_R";
    case TransformStep::Kind::kTranslation: return "I_T";
    case TransformStep::Kind::kMatrix: return "N";  // a glTF node's local matrix
  }
  return "?";
}

bool Orthographic(const Scene& scene) { return scene.viewport.projection == Projection::kOrthographic; }

void PrintHeader(std::ostream& out, const Scene& scene) {
  const Canvas& cv = scene.canvas;
  const Viewport& vp = scene.viewport;
  out << "Scene \"" << scene.name << "\": canvas Cw x Ch = " << cv.width << " x " << cv.height
      << " px, viewport Vw x Vh = " << Num(vp.width) << " x " << Num(vp.height)
      << (Orthographic(scene) ? " (orthographic: d is not used)" : " at distance d = " + Num(vp.distance))
      << ", depth near = " << Num(scene.depth.near) << ", far = " << Num(scene.depth.far)
      << (scene.depth.reversed ? " (reversed Z: near -> 1, far -> 0)" : "") << "\n"
      << "Column vectors on the right: V' = F · V, F = M_Projection · M_Camera · M_Model.\n\n";
}

void PrintProjectionAndCamera(std::ostream& out, const Explanation& e) {
  const Scene& scene = *e.scene;
  out << "M_Projection = CanvasToClip · ViewportToCanvas · P\n";
  PrintMatrix(out,
              Orthographic(scene) ? "P (orthographic: x, y kept, depth row linear in z, w = 1)"
                                  : "P (perspective: x·d, y·d, depth row, w = z)",
              e.p);
  PrintMatrix(out, "ViewportToCanvas (Cw/Vw, Ch/Vh)", e.viewport_to_canvas);
  PrintMatrix(out, "CanvasToClip (Vulkan: 2/Cw, -2/Ch)", e.canvas_to_clip);
  PrintMatrix(out, "M_Projection", e.chain.projection);

  out << "\nM_Camera = C_R⁻¹ · C_T⁻¹  (camera at " << Tuple(scene.camera.position) << ")\n";
  PrintMatrix(out, "C_R⁻¹ (transpose of C_R)", e.camera_rotation_inverse);
  PrintMatrix(out, "C_T⁻¹", e.camera_translation_inverse);
  PrintMatrix(out, "M_Camera", e.chain.camera);
}

void PrintLighting(std::ostream& out, const Explanation& e) {
  const Scene& scene = *e.scene;
  if (!scene.lighting) return;
  if (!e.lighting_used) {
    out << "\nLighting: not used (a wireframe draws edges in the models' own colours)\n";
    return;
  }
  const Lighting& lighting = *scene.lighting;
  out << "\nLighting (Computer Graphics from Scratch's diffuse model, in world space):\n"
      << "  I = ambient + sum of intensity · max(0, n·l) / (|n| |l|), l toward the light; colour = base · min(I, 1)\n"
      << "  ambient " << Num(lighting.ambient) << "\n";
  for (std::size_t i = 0; i < lighting.lights.size(); ++i) {
    const Light& light = lighting.lights[i];
    out << "  light " << i << ": " << (light.kind == Light::Kind::kPoint ? "point at " : "directional, l = ")
        << Tuple(light.vector) << ", intensity " << Num(light.intensity) << "\n";
  }
}

void PrintInstanceCount(std::ostream& out, const Explanation& e) {
  const Scene& scene = *e.scene;
  out << "\nInstances: " << scene.instances.size() << " in all";
  for (const InstanceGrid& g : scene.grids) {
    char grid[256];
    std::snprintf(grid, sizeof grid, "%u x %u x %u grid, spacing (%.6g, %.6g, %.6g)", g.count[0], g.count[1],
                  g.count[2], g.spacing.x, g.spacing.y, g.spacing.z);
    out << "\n  instances[" << g.written << "] of the file is a " << grid << ": "
        << Counted(g.copies(), "copy", "copies") << ", instances " << g.first << ".." << g.first + g.copies() - 1
        << ", i fastest";
  }
  if (!e.options.instance && e.instances.size() < scene.instances.size()) {
    out << "\n  the first " << e.instances.size() << " are traced below; pick any other with --instance I";
  }
  out << "\n";
}

// M_Model's factors as the transform was written, then M_Model, F and the normal matrix.
void PrintInstanceMatrices(std::ostream& out, const InstanceExplanation& x) {
  if (x.steps) {
    const std::size_t n = x.steps->size();
    const bool nodes = std::any_of(x.steps->begin(), x.steps->end(),
                                   [](const StepExplanation& s) { return s.kind == TransformStep::Kind::kMatrix; });
    if (nodes) {
      out << "): a glTF node chain of " << n << " steps, applied in order: the mesh's node, its parents up "
          << "to the root, then the chapter's mirror\n";
    } else {
      out << "): the transform is a list of " << n << " step" << (n == 1 ? "" : "s")
          << ", applied in the order written\n";
    }
    std::string product;
    for (std::size_t k = 0; k < n; ++k) {
      const std::string name = StepName((*x.steps)[k].kind) + std::to_string(k + 1);
      const std::string& label = (*x.steps)[k].label;
      PrintMatrix(out, "step " + std::to_string(k + 1) + ": " + name + (label.empty() ? "" : ", " + label),
                  (*x.steps)[k].matrix);
      product = k == 0 ? name : name + " · " + product;
    }
    if (x.grid_copy) {
      PrintMatrix(out, "I_T (the grid's offset, after the steps)", x.translation);
      product = "I_T · " + product;
    }
    PrintMatrix(out, "M_Model = " + (product.empty() ? std::string("I") : product), x.model_matrix);
  } else {
    out << "): M_Model = I_T · I_R · I_S\n";
    PrintMatrix(out, "I_S", x.scale);
    PrintMatrix(out, "I_R", x.rotation);
    PrintMatrix(out, "I_T", x.translation);
    PrintMatrix(out, "M_Model", x.model_matrix);
  }
  PrintMatrix(out, "F = M_Projection · M_Camera · M_Model", x.f);
  if (x.lit) {
    out << "  lit, " << ShadingName(x.model->shading) << " shading\n";
    if (x.normal_matrix) PrintMatrix(out, "N = (upper 3x3 of M_Model)⁻ᵀ, the normal matrix", *x.normal_matrix);
  }
}

void PrintLight(std::ostream& out, const Scene& scene, const Model& model, const VertexLight& v) {
  const LightTrace& t = v.trace;
  out << "    normal       " << Tuple(t.object_normal) << "   as corner " << v.corner << " of triangle " << v.triangle
      << " uses it"
      << (model.shading == Shading::kFlat ? " (flat: the face normal; the triangle is lit at corner 0 only)" : "")
      << "\n"
      << "    world normal " << Tuple(t.world_normal) << "   = N · normal\n"
      << "    unit normal  " << Tuple(t.unit_normal) << "   renormalised (M_Model · normal would point along "
      << Tuple(t.wrong_normal) << ")\n"
      << "    light        I = ambient " << Num(t.ambient);
  for (std::size_t i = 0; i < t.terms.size(); ++i) {
    const LightTerm& term = t.terms[i];
    const bool point = scene.lighting->lights[i].kind == Light::Kind::kPoint;
    out << "\n                 + light " << i << " (" << (point ? "point" : "directional") << "): l = " << Tuple(term.l)
        << ", n·l = " << Num(term.n_dot_l) << (term.n_dot_l > 0 ? "" : " (faces away: 0)") << ", term "
        << Num(term.contribution);
  }
  const Rgb8 base = CornerBase(model, v.triangle, static_cast<std::size_t>(v.corner));
  out << "\n                 = " << Num(t.intensity)
      << "; colour = " << (model.vertex_colours.empty() ? "base" : "vertex colour") << " (" << int{base.r} << ", "
      << int{base.g} << ", " << int{base.b} << ") / 255 · min(I, 1) = " << Tuple(t.colour) << "\n";
}

void PrintVertex(std::ostream& out, const Scene& scene, const Model& model, const TracedVertex& v) {
  const VertexTrace& tr = v.trace;
  const char* canvas_formula =
      Orthographic(scene) ? "(x·Cw/Vw, y·Ch/Vh), whatever z" : "(x·d·Cw/(z·Vw), y·d·Ch/(z·Vh))";
  out << "  vertex " << v.index << (tr.inside ? "" : "  (outside the clip volume: clipped when drawn)") << "\n"
      << "    object       " << Tuple(tr.object) << "\n"
      << "    world        " << Tuple(tr.world) << "   = M_Model · V\n"
      << "    camera       " << Tuple(tr.camera) << "   = M_Camera · world\n"
      << "    clip         " << Tuple(tr.clip) << "   = M_Projection · camera\n"
      << "    ndc          " << Tuple(tr.ndc) << "   = clip.xyz / clip.w\n"
      << "    canvas       " << Tuple(tr.canvas) << "   = " << canvas_formula << ", +y up\n"
      << "    framebuffer  " << Tuple(glm::dvec2(tr.framebuffer)) << " depth " << Num(tr.framebuffer.z)
      << "   Vulkan: +y down, pixel (i, j) has its centre at (i + 0.5, j + 0.5)\n";
  if (v.light) {
    PrintLight(out, scene, model, *v.light);
  } else if (!model.vertex_colours.empty() && !scene.wireframe && v.index < model.vertex_colours.size()) {
    const Rgb8 c = model.vertex_colours[v.index];
    out << "    colour       (" << int{c.r} << ", " << int{c.g} << ", " << int{c.b}
        << ") / 255, the vertex colour, interpolated across each triangle it is a corner of\n";
  }
}

void PrintInstance(std::ostream& out, const Explanation& e, const InstanceExplanation& x) {
  out << "\nInstance " << x.index << " (model \"" << x.model->name << "\"";
  if (x.grid_copy) {
    const auto& [i, j, k] = x.grid_copy->ijk;
    out << "; copy (" << i << ", " << j << ", " << k << ") of the grid of instances[" << x.grid_copy->grid->written
        << "]";
  }
  PrintInstanceMatrices(out, x);
  if (e.options.vertices == ExplainVertices::kTraced && !e.options.vertex && x.model->vertices.size() > 1) {
    // Which vertex the one trace follows, and how to see the others.
    const TracedVertex& v = x.vertices.front();
    out << "  traced: vertex " << v.index << ", " << (v.trace.inside ? "the first" : "though none") << " of "
        << x.model->vertices.size() << (v.trace.inside ? " inside" : " is inside")
        << " the clip volume (--vertex V for another, --all-vertices for all)\n";
  }
  for (const TracedVertex& v : x.vertices) PrintVertex(out, *e.scene, *x.model, v);
}

}  // namespace

std::string ExplainText(const Explanation& e) {
  std::ostringstream out;
  PrintHeader(out, *e.scene);
  PrintProjectionAndCamera(out, e);
  PrintLighting(out, e);
  PrintInstanceCount(out, e);
  for (const InstanceExplanation& x : e.instances) PrintInstance(out, e, x);
  return out.str();
}

}  // namespace twinraster::explain_report
