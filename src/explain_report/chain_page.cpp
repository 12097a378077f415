#include "explain_report/chain_page.hpp"

#include "base/counted.hpp"
#include "base/trigonometry.hpp"
#include "markup/markup.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <utility>
#include <vector>

namespace twinraster::explain_report {

namespace {

struct P2 {
  double x = 0, y = 0;
};

struct Segment {
  P2 a, b;
  const char* style;  // a CSS class: edge, frustum, far, axis, normal, light
};

struct Mark {
  P2 at;
  std::string label;
  const char* colour;
};

// One panel: what it draws, in its own 2D coordinates (+y up unless y_down), fitted to `fit`.
struct Panel {
  Panel(std::string id_, std::string title_, std::string x, std::string y)
      : id(std::move(id_)), title(std::move(title_)), x_name(std::move(x)), y_name(std::move(y)) {}
  std::string id, title;
  std::string x_name, y_name;  // the axes: "x", "z", ...
  bool y_down = false;
  bool equal_axes = true;
  std::vector<P2> fit;
  std::vector<Segment> segments;
  std::vector<Mark> marks;
  std::vector<std::pair<P2, P2>> boxes;  // outlined rectangles (corner, corner): the NDC square, the canvas
  std::string text;                      // below the drawing: the matrix and the traced vertex, preformatted
};

// Edges a panel draws: at most this many triangles, so that a mesh's page stays small.
constexpr std::size_t kMaxTriangles = 4000;

// Six significant digits (or `digits`), and no "-0" that would puzzle a reader.
std::string Num(double x, int digits = 6) { return markup::Number(x == 0 ? 0.0 : x, digits); }

template <int N>
std::string Vec(const glm::vec<N, double>& v) {
  std::string s = "(";
  for (int i = 0; i < N; ++i) s += (i ? ", " : "") + Num(v[i]);
  return s + ")";
}

// A matrix as the chapter prints it: rows, column vectors on the right.
template <int N>
std::string Matrix(const std::string& name, const glm::mat<N, N, double>& m) {
  std::string s = name + " =\n";
  for (int r = 0; r < N; ++r) {
    s += r == 0 ? "  ⎡" : r + 1 == N ? "  ⎣" : "  ⎢";
    for (int c = 0; c < N; ++c) {
      char cell[32];
      std::snprintf(cell, sizeof cell, "%11.5g", m[c][r] == 0 ? 0.0 : m[c][r]);
      s += cell;
    }
    s += r == 0 ? " ⎤\n" : r + 1 == N ? " ⎦\n" : " ⎥\n";
  }
  return s;
}

// The spaces a panel draws a vertex in.
enum class Space { kObject, kWorld, kCamera, kNdc, kCanvas };

glm::dvec3 Position(const VertexTrace& t, Space space) {
  switch (space) {
    case Space::kObject: return t.object;
    case Space::kWorld: return t.world;
    case Space::kCamera: return t.camera;
    case Space::kNdc: return t.ndc;
    case Space::kCanvas: break;
  }
  return {t.canvas, 0.0};
}

// Which two coordinates of a 3D point a panel shows.
P2 Pick(const glm::dvec3& v, int u, int w) { return {v[u], v[w]}; }
P2 Pick(const VertexTrace& t, Space space, int u, int w) { return Pick(Position(t, space), u, w); }

std::string PanelSvg(const Panel& p) {
  constexpr double kWidth = 400, kHeight = 320, kMargin = 26;
  double x0 = 1e300, x1 = -1e300, y0 = 1e300, y1 = -1e300;
  for (const P2& q : p.fit) {
    if (!std::isfinite(q.x) || !std::isfinite(q.y)) continue;
    x0 = std::min(x0, q.x), x1 = std::max(x1, q.x), y0 = std::min(y0, q.y), y1 = std::max(y1, q.y);
  }
  if (x0 > x1) x0 = -1, x1 = 1, y0 = -1, y1 = 1;
  const double pad_x = std::max((x1 - x0) * 0.08, 1e-9), pad_y = std::max((y1 - y0) * 0.08, 1e-9);
  x0 -= pad_x, x1 += pad_x, y0 -= pad_y, y1 += pad_y;
  double sx = (kWidth - 2 * kMargin) / (x1 - x0), sy = (kHeight - 2 * kMargin) / (y1 - y0);
  if (p.equal_axes) sx = sy = std::min(sx, sy);
  const double cx = (x0 + x1) / 2, cy = (y0 + y1) / 2;
  const auto X = [&](double x) { return markup::Number(kWidth / 2 + (x - cx) * sx, 6); };
  const auto Y = [&](double y) { return markup::Number(kHeight / 2 + (p.y_down ? 1 : -1) * (y - cy) * sy, 6); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"panel\" id=\"" << p.id << "\" width=\"" << kWidth
      << "\" height=\"" << kHeight << "\" viewBox=\"0 0 " << kWidth << " " << kHeight
      << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<defs><clipPath id=\"" << p.id << "-clip\"><rect x=\"1\" y=\"1\" width=\"" << kWidth - 2 << "\" height=\""
      << kHeight - 2 << "\"/></clipPath></defs>\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"#fcfcfc\" stroke=\"#bbb\"/>\n"
      << "<g clip-path=\"url(#" << p.id << "-clip)\">\n";
  // The axes through the origin, where it is in view.
  svg << "<line class=\"axis\" x1=\"0\" y1=\"" << Y(0) << "\" x2=\"" << kWidth << "\" y2=\"" << Y(0) << "\"/>"
      << "<line class=\"axis\" x1=\"" << X(0) << "\" y1=\"0\" x2=\"" << X(0) << "\" y2=\"" << kHeight << "\"/>\n";
  for (const auto& [a, b] : p.boxes) {
    svg << "<rect class=\"box\" x=\"" << X(std::min(a.x, b.x)) << "\" y=\""
        << Y(p.y_down ? std::min(a.y, b.y) : std::max(a.y, b.y)) << "\" width=\""
        << markup::Number(std::abs(b.x - a.x) * sx, 6) << "\" height=\"" << markup::Number(std::abs(b.y - a.y) * sy, 6)
        << "\"/>\n";
  }
  if (!p.segments.empty()) {
    // One path per style keeps a mesh's page small, and so does a segment that starts where the
    // last one ended (a triangle's next edge) continuing the line without a move.
    for (const char* style : {"frustum", "far", "edge", "normal", "light"}) {
      std::string d;
      const P2* end = nullptr;
      for (const Segment& s : p.segments) {
        if (std::string_view(s.style) != style) continue;
        if (!end || end->x != s.a.x || end->y != s.a.y) d += "M" + X(s.a.x) + " " + Y(s.a.y);
        d += "L" + X(s.b.x) + " " + Y(s.b.y);
        end = &s.b;
      }
      if (!d.empty()) svg << "<path class=\"" << style << "\" d=\"" << d << "\"/>\n";
    }
  }
  for (const Mark& m : p.marks) {
    svg << "<circle class=\"mark\" cx=\"" << X(m.at.x) << "\" cy=\"" << Y(m.at.y) << "\" r=\"4\" fill=\"" << m.colour
        << "\"><title>" << markup::Escape(m.label) << "</title></circle><text x=\""
        << markup::Number(kWidth / 2 + (m.at.x - cx) * sx + 6, 6) << "\" y=\""
        << markup::Number(std::stod(Y(m.at.y)) - 6, 6) << "\" fill=\"" << m.colour << "\">" << markup::Escape(m.label)
        << "</text>\n";
  }
  svg << "</g>\n<text x=\"" << kWidth - 6 << "\" y=\"" << kHeight - 6 << "\" text-anchor=\"end\" fill=\"#666\">+"
      << p.x_name << " →, +" << p.y_name << (p.y_down ? " ↓" : " ↑") << "</text>\n</svg>\n";
  return svg.str();
}

// The edges of an instance's triangles in a panel's coordinates; none through a vertex the
// panel cannot show (not traced, or behind the camera in clip space).
void AddEdges(Panel& p, const InstanceExplanation& x, Space space, int u, int w, std::size_t& budget,
              bool need_positive_w = false) {
  std::vector<const VertexTrace*> by_index(x.model->vertices.size(), nullptr);
  for (const TracedVertex& v : x.vertices) {
    if (v.index < by_index.size()) by_index[v.index] = &v.trace;
  }
  for (const Triangle& t : x.model->triangles) {
    if (budget == 0) return;
    --budget;
    std::array<const VertexTrace*, 3> corner{};
    for (std::size_t k = 0; k < 3; ++k) corner[k] = by_index[t.v[k]];
    if (!corner[0] || !corner[1] || !corner[2]) continue;
    if (need_positive_w && (corner[0]->clip.w <= 0 || corner[1]->clip.w <= 0 || corner[2]->clip.w <= 0)) continue;
    for (std::size_t k = 0; k < 3; ++k) {
      const P2 a = Pick(*corner[k], space, u, w), b = Pick(*corner[(k + 1) % 3], space, u, w);
      p.segments.push_back({a, b, "edge"});
      p.fit.push_back(a);
    }
  }
}

void AddFrustum(Panel& p, const Frustum& frustum, int u, int w) {
  for (const auto* plane : {&frustum.near, &frustum.viewport, &frustum.far}) {
    for (std::size_t k = 0; k < 4; ++k) {
      const char* style = plane == &frustum.far ? "far" : "frustum";
      p.segments.push_back({Pick((*plane)[k], u, w), Pick((*plane)[(k + 1) % 4], u, w), style});
    }
  }
  for (std::size_t k = 0; k < 4; ++k) {
    p.segments.push_back({Pick(frustum.eye, u, w), Pick(frustum.far[k], u, w), "frustum"});
  }
  p.fit.push_back(Pick(frustum.eye, u, w));
  for (std::size_t k = 0; k < 4; ++k) p.fit.push_back(Pick(frustum.viewport[k], u, w));
  p.marks.push_back({Pick(frustum.eye, u, w), "camera", "#444"});
}

std::string Figure(const Panel& p) {
  return "<figure class=\"chain-panel\" data-panel=\"" + p.id + "\"><figcaption><b>" + markup::Escape(p.title) +
         "</b></figcaption>" + PanelSvg(p) + "<pre>" + markup::Escape(p.text) + "</pre></figure>\n";
}

// What every panel reads: the explanation, the traced instance and vertex, and whether every
// explained instance's edges fit.
struct Trace {
  const Explanation& e;
  const InstanceExplanation& traced;
  const VertexTrace& v;
  const std::optional<VertexLight>& light;
  bool all_instances;  // every explained instance's edges fit in kMaxTriangles
};

constexpr const char* kTraced = "#d0021b";

std::string PixelText(const glm::dvec3& framebuffer) {
  return "pixel (" + Num(std::floor(framebuffer.x), 10) + ", " + Num(std::floor(framebuffer.y), 10) + ")";
}

// The edges of the explained instances (or only the traced one, for a large mesh) in one space.
void EachInstance(const Trace& t, Panel& p, Space space, int u, int w, bool need_positive_w) {
  std::size_t budget = kMaxTriangles;
  for (const InstanceExplanation& x : t.e.instances) {
    if (t.all_instances || &x == &t.traced) AddEdges(p, x, space, u, w, budget, need_positive_w);
  }
}

void TracedEdges(const Trace& t, Panel& p, Space space, int u, int w) {
  std::size_t budget = kMaxTriangles;
  AddEdges(p, t.traced, space, u, w, budget);
}

// Edges whose ends were projected from near w = 0 run off to thousands of units: not drawn.
void DropFarSegments(Panel& p, double limit) {
  const auto far = [limit](const Segment& s) {
    return std::abs(s.a.x) > limit || std::abs(s.a.y) > limit || std::abs(s.b.x) > limit || std::abs(s.b.y) > limit;
  };
  p.segments.erase(std::remove_if(p.segments.begin(), p.segments.end(), far), p.segments.end());
}

Panel ModelPanel(const Trace& t, const std::string& instance_name, const std::string& vertex_name) {
  Panel p("model", "1. Model space: " + instance_name, "x", "y");  // from the front
  TracedEdges(t, p, Space::kObject, 0, 1);
  p.marks.push_back({Pick(t.v.object, 0, 1), "V", kTraced});
  p.fit.push_back(Pick(t.v.object, 0, 1));
  p.text = "V, " + vertex_name + " as the model lists it:\n  V = " + Vec(t.v.object) + "\n";
  return p;
}

// A transform written as a list, or a glTF node chain: each step's matrix by its label, in the
// order applied, before their product M_Model. Nothing for the object form, whose factors the
// text explain prints.
std::string ModelFactors(const InstanceExplanation& x) {
  if (!x.steps) return "";
  std::string s;
  for (std::size_t k = 0; k < x.steps->size(); ++k) {
    const StepExplanation& step = (*x.steps)[k];
    s += Matrix("step " + std::to_string(k + 1) + (step.label.empty() ? "" : ": " + step.label), step.matrix);
  }
  return s + "M_Model = step " + std::to_string(x.steps->size()) + " · … · step 1" +
         (x.grid_copy ? ", then the grid's offset" : "") + "\n";
}

// The world seen along -y (x right, z up the page) or along -x (z right, y up).
Panel WorldPanel(const Trace& t, bool from_above) {
  const int u = from_above ? 0 : 2, w = from_above ? 2 : 1;
  Panel p(from_above ? "world-top" : "world-side",
          from_above ? "2. World, from above: the instances, the camera and its frustum" : "3. World, from the side",
          from_above ? "x" : "z", from_above ? "z" : "y");
  EachInstance(t, p, Space::kWorld, u, w, false);
  AddFrustum(p, t.e.world_frustum, u, w);
  p.marks.push_back({Pick(t.v.world, u, w), "M_Model·V", kTraced});
  if (from_above) {
    p.text =
        ModelFactors(t.traced) + Matrix("M_Model", t.traced.model_matrix) + "M_Model · V = " + Vec(t.v.world) + "\n";
  } else {
    const Scene& scene = *t.e.scene;
    p.text = "near plane z = " + Num(scene.depth.near) + ", viewport at d = " + Num(scene.viewport.distance) +
             ", far plane z = " +
             (std::isinf(scene.depth.far) ? std::string("infinite (drawn at ") + Num(DrawnFar(scene)) + ")"
                                          : Num(scene.depth.far)) +
             " (camera space)\n";
  }
  return p;
}

Panel CameraPanel(const Trace& t) {
  Panel p("camera", "4. Camera space, from above: the camera at the origin looking along +z", "x", "z");
  EachInstance(t, p, Space::kCamera, 0, 2, false);
  AddFrustum(p, t.e.camera_frustum, 0, 2);
  p.marks.push_back({Pick(t.v.camera, 0, 2), "M_Camera·M_Model·V", kTraced});
  p.text = Matrix("M_Camera", t.e.chain.camera) + "M_Camera · M_Model · V = " + Vec(t.v.camera) + "\n";
  return p;
}

// Clip space divided by w: NDC, Vulkan's x right and y down, depth in [0, 1].
Panel NdcPanel(const Trace& t) {
  Panel p("ndc", "5. Clip space and NDC (Vulkan: +y down)", "x", "y");
  p.y_down = true;
  EachInstance(t, p, Space::kNdc, 0, 1, true);
  DropFarSegments(p, 1e3);
  p.fit = {{-1.15, -1.15}, {1.15, 1.15}};
  p.boxes.push_back({{-1, -1}, {1, 1}});
  p.marks.push_back({Pick(t.v.ndc, 0, 1), "NDC", kTraced});
  const bool orthographic = t.e.scene->viewport.projection == Projection::kOrthographic;
  p.text = Matrix("M_Projection", t.e.chain.projection) + "clip = M_Projection · camera = " + Vec(t.v.clip) +
           "\nNDC = clip.xyz / w = " + Vec(t.v.ndc) + "\n" +
           (t.v.inside ? "inside the clip volume: -w ≤ x, y ≤ w, 0 ≤ z ≤ w\n" : "outside the clip volume: clipped\n") +
           (orthographic ? "orthographic: w = 1, nothing is divided\n" : "perspective: w = camera z\n");
  return p;
}

// The chapter's canvas: origin at the centre, +y up; and the pixel Vulkan writes.
Panel CanvasPanel(const Trace& t) {
  const double cw = t.e.scene->canvas.width, ch = t.e.scene->canvas.height;
  Panel p("canvas", "6. The canvas, and the pixel", "x", "y");
  EachInstance(t, p, Space::kCanvas, 0, 1, true);
  DropFarSegments(p, 1e3 * std::max(cw, ch));
  p.fit = {{-cw / 2 * 1.05, -ch / 2 * 1.05}, {cw / 2 * 1.05, ch / 2 * 1.05}};
  p.boxes.push_back({{-cw / 2, -ch / 2}, {cw / 2, ch / 2}});
  const glm::dvec3& fb = t.v.framebuffer;
  p.marks.push_back({{t.v.canvas.x, t.v.canvas.y}, PixelText(fb), kTraced});
  p.text = Matrix("F = M_Projection · M_Camera · M_Model", t.traced.f) +
           Matrix("ViewportToCanvas", t.e.viewport_to_canvas) +
           "canvas (origin at the centre, +y up) = " + Vec(t.v.canvas) +
           "\nframebuffer (Vulkan: origin top-left, +y down) = " + Vec(fb) + "\n" + PixelText(fb) + ", depth " +
           Num(fb.z) + "\n";
  return p;
}

// Each light's arrow from the traced vertex, and its term as text.
std::string LightArrows(const Trace& t, Panel& p, P2 at, double extent, int u, int w) {
  std::string terms;
  const std::vector<LightTerm>& all = t.light->trace.terms;
  for (std::size_t k = 0; k < all.size(); ++k) {
    const glm::dvec3& l = all[k].l;
    const double length = Hypotenuse(l.x, l.y, l.z);
    if (length > 0) {
      const P2 towards{at.x + l[u] / length * extent, at.y + l[w] / length * extent};
      p.segments.push_back({at, towards, "light"});
      p.fit.push_back(towards);
      p.marks.push_back({towards, "L" + std::to_string(k + 1), "#b8860b"});
    }
    const bool point = t.e.scene->lighting->lights[k].kind == Light::Kind::kPoint;
    terms += "  L" + std::to_string(k + 1) + " (" + (point ? "point" : "directional") + "): l = " + Vec(l) +
             ", n·l = " + Num(all[k].n_dot_l) + ", term = " + Num(all[k].contribution) + "\n";
  }
  return terms;
}

// The light at the traced vertex: its normal and each light's direction, in the world seen along
// the axis the normal has least of, so that the normal lies nearly in the page.
Panel LightPanel(const Trace& t) {
  const LightTrace& light = t.light->trace;
  const glm::dvec3& n = light.unit_normal;
  const std::array<double, 3> size = {std::abs(n.x), std::abs(n.y), std::abs(n.z)};
  const int dropped = size[0] <= size[1] && size[0] <= size[2] ? 0 : size[1] <= size[2] ? 1 : 2;
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  // The page shows (x, y) along z, (z, y) along x, (x, z) along y: y stays up where it is shown.
  const int u = dropped == 0 ? 2 : 0, w = dropped == 1 ? 2 : 1;
  Panel p("light", std::string("7. Light: the normal, N and the lights (world, seen along ") + kAxis[dropped] + ")",
          kAxis[u], kAxis[w]);
  const P2 at = Pick(t.v.world, u, w);
  double extent = 0;  // arrows half as long as the instance is wide
  for (const TracedVertex& x : t.traced.vertices) {
    const P2 q = Pick(x.trace.world, u, w);
    extent = std::max(extent, Hypotenuse(q.x - at.x, q.y - at.y));
  }
  extent = std::max(extent, 1e-6) * 0.5;
  TracedEdges(t, p, Space::kWorld, u, w);
  const P2 tip{at.x + n[u] * extent, at.y + n[w] * extent};
  p.segments.push_back({at, tip, "normal"});
  p.marks.push_back({tip, "n", "#1a7f37"});
  p.fit.push_back(tip);
  const std::string terms = LightArrows(t, p, at, extent, u, w);
  p.marks.push_back({at, "V", kTraced});
  const std::optional<glm::dmat3>& normal_matrix = t.traced.normal_matrix;
  p.text = (normal_matrix ? Matrix("N = (M_Model's upper 3x3)⁻ᵀ", *normal_matrix) : std::string("N: none\n")) +
           "n (model) = " + Vec(light.object_normal) + "\nN · n = " + Vec(light.world_normal) +
           "\nunit normal = " + Vec(n) + "\n(M_Model · n would give " + Vec(light.wrong_normal) +
           ")\nambient = " + Num(light.ambient) + "\n" + terms + "I = " + Num(light.intensity) +
           ", colour = " + Vec(light.colour) + "\n";
  return p;
}

// The page's head, its style sheet and title: what stays when the chain changes.
std::string PageHead(const Explanation& e) {
  const std::string& scene_name = e.scene->name;
  std::ostringstream page;
  page << markup::PageStart("The chain of " + scene_name) << "<style>.axis{stroke:#ddd}.box{fill:none;stroke:#555}"
       << ".edge{fill:none;stroke:#2b6cb0;stroke-width:1}.frustum{fill:none;stroke:#999;stroke-dasharray:4 3}"
       << ".far{fill:none;stroke:#bbb;stroke-dasharray:2 4}.normal{stroke:#1a7f37;stroke-width:2}"
       << ".light{stroke:#b8860b;stroke-width:2}figure.chain-panel{width:402px}"
       << "figure.chain-panel pre{white-space:pre-wrap}</style>\n"
       << "<h1>The chain of " << markup::Escape(scene_name) << "</h1>\n";
  return page.str();
}

std::string Introduction(const Explanation& e, const Trace& t, const std::string& instance_name,
                         const std::string& vertex_name) {
  std::ostringstream text;
  text << "<p>F = M_Projection · M_Camera · M_Model, computed in double by the host, takes "
       << markup::Escape(vertex_name) << " of " << markup::Escape(instance_name)
       << " from model space to the canvas. Each panel draws one space with the "
       << "matrix that leads into it and where the vertex (red) lands there. " << e.instances.size() << " of "
       << Counted(e.scene->instances.size(), "instance") << " shown"
       << (t.all_instances ? "" : " (edges of the traced instance only: the mesh is large)") << ".</p>\n";
  return text.str();
}

}  // namespace

std::string ChainPageHead(const Explanation& e) { return PageHead(e); }

std::string ChainPanelsHtml(const Explanation& e) {
  // A scene always has an instance and a model a vertex; an explanation without them is a caller's mistake.
  if (e.instances.empty() || e.instances.front().vertices.empty()) {
    throw std::invalid_argument("ChainPanelsHtml: the explanation traces no vertex");
  }
  const InstanceExplanation& traced = e.instances.front();
  const TracedVertex& v = traced.vertices.at(traced.traced);
  std::size_t total = 0;  // triangles over the instances explained
  for (const InstanceExplanation& x : e.instances) total += x.model->triangles.size();
  const Trace t{e, traced, v.trace, v.light, total <= kMaxTriangles};
  const std::string instance_name =
      "instance " + std::to_string(traced.index) + " (model \"" + traced.model->name + "\")";
  const std::string vertex_name = "vertex " + std::to_string(v.index);

  std::vector<Panel> panels = {ModelPanel(t, instance_name, vertex_name),
                               WorldPanel(t, true),
                               WorldPanel(t, false),
                               CameraPanel(t),
                               NdcPanel(t),
                               CanvasPanel(t)};
  if (v.light) panels.push_back(LightPanel(t));
  std::string html = Introduction(e, t, instance_name, vertex_name);
  for (const Panel& p : panels) html += Figure(p);
  return html;
}

std::string ChainPageHtml(const Explanation& e) {
  std::string page = PageHead(e);
  page += ChainPanelsHtml(e);
  page += markup::kPageEnd;
  return page;
}

}  // namespace twinraster::explain_report
