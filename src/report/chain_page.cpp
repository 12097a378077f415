#include "report/chain_page.hpp"

#include "report/markup.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <sstream>
#include <utility>
#include <vector>

namespace twinraster::report {

namespace {

using Json = nlohmann::ordered_json;

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

double At(const Json& array, std::size_t i) { return array.at(i).get<double>(); }

std::string Vec(const Json& v) {
  std::string s = "(";
  for (std::size_t i = 0; i < v.size(); ++i) s += (i ? ", " : "") + Number(At(v, i), 6);
  return s + ")";
}

// A matrix as the chapter prints it: rows, column vectors on the right.
std::string Matrix(const std::string& name, const Json& rows) {
  std::string s = name + " =\n";
  for (std::size_t r = 0; r < rows.size(); ++r) {
    s += r == 0 ? "  ⎡" : r + 1 == rows.size() ? "  ⎣" : "  ⎢";
    for (std::size_t c = 0; c < rows[r].size(); ++c) {
      char cell[32];
      std::snprintf(cell, sizeof cell, "%11.5g", At(rows[r], c));
      s += cell;
    }
    s += r == 0 ? " ⎤\n" : r + 1 == rows.size() ? " ⎦\n" : " ⎥\n";
  }
  return s;
}

// Which two coordinates of a 3D point a panel shows.
P2 Pick(const Json& v, int u, int w) { return {At(v, static_cast<std::size_t>(u)), At(v, static_cast<std::size_t>(w))}; }

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
  const auto X = [&](double x) { return Number(kWidth / 2 + (x - cx) * sx, 6); };
  const auto Y = [&](double y) { return Number(kHeight / 2 + (p.y_down ? 1 : -1) * (y - cy) * sy, 6); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" class=\"panel\" id=\"" << p.id << "\" width=\"" << kWidth << "\" height=\""
      << kHeight << "\" viewBox=\"0 0 " << kWidth << " " << kHeight << "\" font-family=\"sans-serif\" font-size=\"11\">\n"
      << "<defs><clipPath id=\"" << p.id << "-clip\"><rect x=\"1\" y=\"1\" width=\"" << kWidth - 2 << "\" height=\""
      << kHeight - 2 << "\"/></clipPath></defs>\n<rect width=\"100%\" height=\"100%\" fill=\"#fcfcfc\" stroke=\"#bbb\"/>\n"
      << "<g clip-path=\"url(#" << p.id << "-clip)\">\n";
  // The axes through the origin, where it is in view.
  svg << "<line class=\"axis\" x1=\"0\" y1=\"" << Y(0) << "\" x2=\"" << kWidth << "\" y2=\"" << Y(0) << "\"/>"
      << "<line class=\"axis\" x1=\"" << X(0) << "\" y1=\"0\" x2=\"" << X(0) << "\" y2=\"" << kHeight << "\"/>\n";
  for (const auto& [a, b] : p.boxes) {
    svg << "<rect class=\"box\" x=\"" << X(std::min(a.x, b.x)) << "\" y=\""
        << Y(p.y_down ? std::min(a.y, b.y) : std::max(a.y, b.y)) << "\" width=\"" << Number(std::abs(b.x - a.x) * sx, 6)
        << "\" height=\"" << Number(std::abs(b.y - a.y) * sy, 6) << "\"/>\n";
  }
  if (!p.segments.empty()) {
    // One path per style keeps a mesh's page small.
    for (const char* style : {"frustum", "far", "edge", "normal", "light"}) {
      std::string d;
      for (const Segment& s : p.segments) {
        if (std::string_view(s.style) != style) continue;
        d += "M" + X(s.a.x) + " " + Y(s.a.y) + "L" + X(s.b.x) + " " + Y(s.b.y);
      }
      if (!d.empty()) svg << "<path class=\"" << style << "\" d=\"" << d << "\"/>\n";
    }
  }
  for (const Mark& m : p.marks) {
    svg << "<circle class=\"mark\" cx=\"" << X(m.at.x) << "\" cy=\"" << Y(m.at.y) << "\" r=\"4\" fill=\"" << m.colour
        << "\"><title>" << Escape(m.label) << "</title></circle><text x=\"" << Number(kWidth / 2 + (m.at.x - cx) * sx + 6, 6)
        << "\" y=\"" << Number(std::stod(Y(m.at.y)) - 6, 6) << "\" fill=\"" << m.colour << "\">" << Escape(m.label)
        << "</text>\n";
  }
  svg << "</g>\n<text x=\"" << kWidth - 6 << "\" y=\"" << kHeight - 6 << "\" text-anchor=\"end\" fill=\"#666\">+"
      << p.x_name << " →, +" << p.y_name << (p.y_down ? " ↓" : " ↑") << "</text>\n</svg>\n";
  return svg.str();
}

// The edges of an instance's triangles in a panel's coordinates; none through a vertex the
// panel cannot show (behind the camera in clip space).
void AddEdges(Panel& p, const Model& model, const Json& vertices, const char* space, int u, int w, std::size_t& budget,
              bool need_positive_w = false) {
  std::vector<const Json*> by_index(model.vertices.size(), nullptr);
  for (const Json& v : vertices) {
    const auto index = v.at("index").get<std::size_t>();
    if (index < by_index.size()) by_index[index] = &v;
  }
  for (const Triangle& t : model.triangles) {
    if (budget == 0) return;
    --budget;
    std::array<const Json*, 3> corner{};
    for (int k = 0; k < 3; ++k) corner[static_cast<std::size_t>(k)] = by_index[t.v[static_cast<std::size_t>(k)]];
    if (!corner[0] || !corner[1] || !corner[2]) continue;
    if (need_positive_w && (At(corner[0]->at("clip"), 3) <= 0 || At(corner[1]->at("clip"), 3) <= 0 || At(corner[2]->at("clip"), 3) <= 0)) {
      continue;
    }
    for (int k = 0; k < 3; ++k) {
      const Json& a = corner[static_cast<std::size_t>(k)]->at(space);
      const Json& b = corner[static_cast<std::size_t>((k + 1) % 3)]->at(space);
      p.segments.push_back({Pick(a, u, w), Pick(b, u, w), "edge"});
      p.fit.push_back(Pick(a, u, w));
    }
  }
}

void AddFrustum(Panel& p, const Json& frustum, int u, int w) {
  const Json& eye = frustum.at("eye");
  for (const char* plane : {"near", "viewport", "far"}) {
    const Json& c = frustum.at(plane);
    for (std::size_t k = 0; k < 4; ++k) {
      p.segments.push_back({Pick(c.at(k), u, w), Pick(c.at((k + 1) % 4), u, w), std::string_view(plane) == "far" ? "far" : "frustum"});
    }
  }
  for (std::size_t k = 0; k < 4; ++k) p.segments.push_back({Pick(eye, u, w), Pick(frustum.at("far").at(k), u, w), "frustum"});
  p.fit.push_back(Pick(eye, u, w));
  for (std::size_t k = 0; k < 4; ++k) p.fit.push_back(Pick(frustum.at("viewport").at(k), u, w));
  p.marks.push_back({Pick(eye, u, w), "camera", "#444"});
}

const Model* FindModel(const Scene& scene, const std::string& name) {
  for (const Model& m : scene.models) {
    if (m.name == name) return &m;
  }
  return nullptr;
}

std::string Figure(const Panel& p) {
  return "<figure class=\"chain-panel\" data-panel=\"" + p.id + "\"><figcaption><b>" + Escape(p.title) + "</b></figcaption>" +
         PanelSvg(p) + "<pre>" + Escape(p.text) + "</pre></figure>\n";
}

// What every panel reads: the explain object, the traced instance and vertex, and how many
// instances' edges fit.
struct Trace {
  const Scene& scene;
  const Json& e;
  std::size_t instance;  // index into e["instances"]
  const Json& traced;    // e["instances"][instance]
  const Json& v;         // its traced vertex
  bool all_instances;    // every shown instance's edges fit in kMaxTriangles
};

constexpr const char* kTraced = "#d0021b";

std::string PixelText(const Json& framebuffer) {
  return "pixel (" + Number(std::floor(At(framebuffer, 0)), 10) + ", " + Number(std::floor(At(framebuffer, 1)), 10) + ")";
}

// The edges of the shown instances (or only the traced one, for a large mesh) in one space.
void EachInstance(const Trace& t, Panel& p, const char* space, int u, int w, bool need_positive_w) {
  std::size_t budget = kMaxTriangles;
  const Json& instances = t.e.at("instances");
  for (std::size_t i = 0; i < instances.size(); ++i) {
    if (!t.all_instances && i != t.instance) continue;
    const Model* m = FindModel(t.scene, instances[i].at("model").get<std::string>());
    if (m) AddEdges(p, *m, instances[i].at("vertices"), space, u, w, budget, need_positive_w);
  }
}

void TracedEdges(const Trace& t, Panel& p, const char* space, int u, int w) {
  std::size_t budget = kMaxTriangles;
  if (const Model* m = FindModel(t.scene, t.traced.at("model").get<std::string>())) {
    AddEdges(p, *m, t.traced.at("vertices"), space, u, w, budget);
  }
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
  TracedEdges(t, p, "object", 0, 1);
  p.marks.push_back({Pick(t.v.at("object"), 0, 1), "V", kTraced});
  p.fit.push_back(Pick(t.v.at("object"), 0, 1));
  p.text = "V, " + vertex_name + " as the model lists it:\n  V = " + Vec(t.v.at("object")) + "\n";
  return p;
}

// The world seen along -y (x right, z up the page) or along -x (z right, y up).
Panel WorldPanel(const Trace& t, bool from_above) {
  const int u = from_above ? 0 : 2, w = from_above ? 2 : 1;
  Panel p(from_above ? "world-top" : "world-side",
          from_above ? "2. World, from above: the instances, the camera and its frustum" : "3. World, from the side",
          from_above ? "x" : "z", from_above ? "z" : "y");
  EachInstance(t, p, "world", u, w, false);
  AddFrustum(p, t.e.at("frustum").at("world"), u, w);
  p.marks.push_back({Pick(t.v.at("world"), u, w), "M_Model·V", kTraced});
  if (from_above) {
    p.text = Matrix("M_Model", t.traced.at("model_matrix")) + "M_Model · V = " + Vec(t.v.at("world")) + "\n";
  } else {
    char planes[256];
    std::snprintf(planes, sizeof planes, "near plane z = %g, viewport at d = %g, far plane z = %g (camera space)\n",
                  t.e.at("depth").at("near").get<double>(), t.e.at("viewport").at("distance").get<double>(),
                  t.e.at("depth").at("far").get<double>());
    p.text = planes;
  }
  return p;
}

Panel CameraPanel(const Trace& t) {
  Panel p("camera", "4. Camera space, from above: the camera at the origin looking along +z", "x", "z");
  EachInstance(t, p, "camera", 0, 2, false);
  AddFrustum(p, t.e.at("frustum").at("camera"), 0, 2);
  p.marks.push_back({Pick(t.v.at("camera"), 0, 2), "M_Camera·M_Model·V", kTraced});
  p.text = Matrix("M_Camera", t.e.at("camera_matrix")) + "M_Camera · M_Model · V = " + Vec(t.v.at("camera")) + "\n";
  return p;
}

// Clip space divided by w: NDC, Vulkan's x right and y down, depth in [0, 1].
Panel NdcPanel(const Trace& t) {
  Panel p("ndc", "5. Clip space and NDC (Vulkan: +y down)", "x", "y");
  p.y_down = true;
  EachInstance(t, p, "ndc", 0, 1, true);
  DropFarSegments(p, 1e3);
  p.fit = {{-1.15, -1.15}, {1.15, 1.15}};
  p.boxes.push_back({{-1, -1}, {1, 1}});
  p.marks.push_back({Pick(t.v.at("ndc"), 0, 1), "NDC", kTraced});
  const bool orthographic = t.e.at("viewport").at("projection") == "orthographic";
  p.text = Matrix("M_Projection", t.e.at("projection_matrix")) + "clip = M_Projection · camera = " + Vec(t.v.at("clip")) +
           "\nNDC = clip.xyz / w = " + Vec(t.v.at("ndc")) + "\n" +
           (t.v.at("inside_clip_volume").get<bool>() ? "inside the clip volume: -w ≤ x, y ≤ w, 0 ≤ z ≤ w\n"
                                                     : "outside the clip volume: clipped\n") +
           (orthographic ? "orthographic: w = 1, nothing is divided\n" : "perspective: w = camera z\n");
  return p;
}

// The chapter's canvas: origin at the centre, +y up; and the pixel Vulkan writes.
Panel CanvasPanel(const Trace& t) {
  const double cw = t.e.at("canvas").at("width").get<double>(), ch = t.e.at("canvas").at("height").get<double>();
  Panel p("canvas", "6. The canvas, and the pixel", "x", "y");
  EachInstance(t, p, "canvas", 0, 1, true);
  DropFarSegments(p, 1e3 * std::max(cw, ch));
  p.fit = {{-cw / 2 * 1.05, -ch / 2 * 1.05}, {cw / 2 * 1.05, ch / 2 * 1.05}};
  p.boxes.push_back({{-cw / 2, -ch / 2}, {cw / 2, ch / 2}});
  const Json& fb = t.v.at("framebuffer");
  p.marks.push_back({Pick(t.v.at("canvas"), 0, 1), PixelText(fb), kTraced});
  p.text = Matrix("F = M_Projection · M_Camera · M_Model", t.traced.at("mvp")) +
           Matrix("ViewportToCanvas", t.e.at("viewport_to_canvas")) + "canvas (origin at the centre, +y up) = " +
           Vec(t.v.at("canvas")) + "\nframebuffer (Vulkan: origin top-left, +y down) = " + Vec(fb) + "\n" + PixelText(fb) +
           ", depth " + Number(At(fb, 2), 6) + "\n";
  return p;
}

// The light at the traced vertex: its normal and each light's direction, in the world seen along
// the axis the normal has least of, so that the normal lies nearly in the page.
Panel LightPanel(const Trace& t) {
  const Json& light = t.v.at("light");
  const Json& n = light.at("unit_normal");
  const std::array<double, 3> size = {std::abs(At(n, 0)), std::abs(At(n, 1)), std::abs(At(n, 2))};
  const int dropped = size[0] <= size[1] && size[0] <= size[2] ? 0 : size[1] <= size[2] ? 1 : 2;
  static constexpr const char* kAxis[] = {"x", "y", "z"};
  // The page shows (x, y) along z, (z, y) along x, (x, z) along y: y stays up where it is shown.
  const int u = dropped == 0 ? 2 : 0, w = dropped == 1 ? 2 : 1;
  Panel p("light", std::string("7. Light: the normal, N and the lights (world, seen along ") + kAxis[dropped] + ")",
          kAxis[u], kAxis[w]);
  const P2 at = Pick(t.v.at("world"), u, w);
  double extent = 0;  // arrows half as long as the instance is wide
  for (const Json& x : t.traced.at("vertices")) {
    const P2 q = Pick(x.at("world"), u, w);
    extent = std::max(extent, std::hypot(q.x - at.x, q.y - at.y));
  }
  extent = std::max(extent, 1e-6) * 0.5;
  TracedEdges(t, p, "world", u, w);
  const P2 tip{at.x + At(n, static_cast<std::size_t>(u)) * extent, at.y + At(n, static_cast<std::size_t>(w)) * extent};
  p.segments.push_back({at, tip, "normal"});
  p.marks.push_back({tip, "n", "#1a7f37"});
  p.fit.push_back(tip);
  std::string terms;
  const Json& lights = t.e.at("lighting").at("lights");
  for (std::size_t k = 0; k < light.at("terms").size(); ++k) {
    const Json& term = light.at("terms").at(k);
    const Json& l = term.at("l");
    const double length = std::hypot(At(l, 0), At(l, 1), At(l, 2));
    if (length > 0) {
      const P2 towards{at.x + At(l, static_cast<std::size_t>(u)) / length * extent,
                       at.y + At(l, static_cast<std::size_t>(w)) / length * extent};
      p.segments.push_back({at, towards, "light"});
      p.fit.push_back(towards);
      p.marks.push_back({towards, "L" + std::to_string(k + 1), "#b8860b"});
    }
    terms += "  L" + std::to_string(k + 1) + " (" + lights.at(k).at("type").get<std::string>() + "): l = " + Vec(l) +
             ", n·l = " + Number(term.at("n_dot_l").get<double>(), 6) + ", term = " +
             Number(term.at("contribution").get<double>(), 6) + "\n";
  }
  p.marks.push_back({at, "V", kTraced});
  const Json& normal_matrix = t.traced.at("normal_matrix");
  p.text = (normal_matrix.is_null() ? std::string("N: none\n") : Matrix("N = (M_Model's upper 3x3)⁻ᵀ", normal_matrix)) +
           "n (model) = " + Vec(light.at("normal")) + "\nN · n = " + Vec(light.at("world_normal")) +
           "\nunit normal = " + Vec(n) + "\n(M_Model · n would give " + Vec(light.at("normal_by_model_matrix")) +
           ")\nambient = " + Number(light.at("ambient").get<double>(), 6) + "\n" + terms +
           "I = " + Number(light.at("intensity").get<double>(), 6) + ", colour = " + Vec(light.at("colour")) + "\n";
  return p;
}

// The traced vertex: the one asked for, or the first the camera sees.
std::size_t PickVertex(const Json& vertices, const std::optional<std::size_t>& asked) {
  if (asked) return *asked;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (vertices[i].at("inside_clip_volume").get<bool>()) return i;
  }
  return 0;
}

}  // namespace

std::string ChainPageHtml(const Scene& scene, const Json& e, const ChainPageOptions& options) {
  const Json& instances = e.at("instances");
  const Json& traced = instances.at(options.instance);
  const Json& v = traced.at("vertices").at(PickVertex(traced.at("vertices"), options.vertex));
  std::size_t total = 0;  // triangles over the instances shown
  for (const Json& x : instances) {
    if (const Model* m = FindModel(scene, x.at("model").get<std::string>())) total += m->triangles.size();
  }
  const Trace t{scene, e, options.instance, traced, v, total <= kMaxTriangles};
  const std::string instance_name = "instance " + std::to_string(traced.at("index").get<std::size_t>()) + " (model \"" +
                                    traced.at("model").get<std::string>() + "\")";
  const std::string vertex_name = "vertex " + std::to_string(v.at("index").get<std::size_t>());

  std::vector<Panel> panels = {ModelPanel(t, instance_name, vertex_name), WorldPanel(t, true), WorldPanel(t, false),
                               CameraPanel(t), NdcPanel(t), CanvasPanel(t)};
  if (v.contains("light") && !v.at("light").is_null()) panels.push_back(LightPanel(t));

  std::ostringstream page;
  const std::string scene_name = e.at("scene").get<std::string>();
  page << PageStart("The chain of " + scene_name) << "<style>.axis{stroke:#ddd}.box{fill:none;stroke:#555}"
       << ".edge{fill:none;stroke:#2b6cb0;stroke-width:1}.frustum{fill:none;stroke:#999;stroke-dasharray:4 3}"
       << ".far{fill:none;stroke:#bbb;stroke-dasharray:2 4}.normal{stroke:#1a7f37;stroke-width:2}"
       << ".light{stroke:#b8860b;stroke-width:2}figure.chain-panel{width:402px}figure.chain-panel pre{white-space:pre-wrap}</style>\n"
       << "<h1>The chain of " << Escape(scene_name) << "</h1>\n<p>F = M_Projection · M_Camera · M_Model, computed in double by "
       << "the host, takes " << Escape(vertex_name) << " of " << Escape(instance_name)
       << " from model space to the canvas. Each panel draws one space with the matrix that leads into it and where the "
       << "vertex (red) lands there. " << instances.size() << " of " << e.at("instance_count").get<std::size_t>()
       << " instances shown" << (t.all_instances ? "" : " (edges of the traced instance only: the mesh is large)")
       << ".</p>\n";
  for (const Panel& p : panels) page << Figure(p);
  page << kPageEnd;
  return page.str();
}

}  // namespace twinraster::report
