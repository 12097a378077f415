#include "verify/verifier.hpp"

#include "truth/truth_renderer.hpp"
#include "verify/pixel_judge.hpp"

#include <algorithm>
#include <optional>
#include <unordered_map>
#include <stdexcept>
#include <string>

namespace twinraster::verify {

namespace {

void CheckInputs(const Scene& scene, const DrawList& list, const Image& image, const VerifyOptions& options) {
  ValidateDrawList(list);
  if (image.width != list.width || image.height != list.height) {
    throw std::invalid_argument("the image is " + std::to_string(image.width) + " x " + std::to_string(image.height) +
                                ", but the scene's canvas is " + std::to_string(list.width) + " x " +
                                std::to_string(list.height));
  }
  if (scene.instances.size() != list.draws.size() || scene.models.size() != list.meshes.size()) {
    throw std::invalid_argument("the draw list was not built from this scene");
  }
  if (options.subpixel_bits < 0 || options.subpixel_bits > 24) {
    throw std::invalid_argument("subpixel bits must be 0 to 24, not " + std::to_string(options.subpixel_bits));
  }
}

// visit(x, y, centre, coverage) for each pixel of `box` the shape may cover.
template <class Shape, class Visit>
void Scan(const Shape& shape, const PixelBox& box, Visit&& visit) {
  for (int y = box.y0; y <= box.y1; ++y) {
    for (int x = box.x0; x <= box.x1; ++x) {
      const glm::dvec2 centre(x + 0.5, y + 0.5);
      const Coverage c = shape.Covers(centre);
      if (c != Coverage::kOut) visit(x, y, centre, c);
    }
  }
}

// For each triangle's edge i (tri[i] -> tri[i + 1]), the one other triangle of the mesh sharing it
// and that triangle's edge index, or -1 where the edge is a border or shared by more than two.
struct Neighbour {
  std::int32_t triangle = -1;
  std::int32_t edge = -1;
};
std::vector<std::array<Neighbour, 3>> MeshNeighbours(const DrawMesh& mesh) {
  struct Sharing {
    Neighbour first, second;
    int count = 0;
  };
  std::unordered_map<std::uint64_t, Sharing> edges;
  edges.reserve(mesh.triangles.size() * 2);
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = mesh.triangles[t][i], b = mesh.triangles[t][(i + 1) % 3];
      Sharing& s = edges[(std::uint64_t{std::min(a, b)} << 32) | std::max(a, b)];
      (s.count == 0 ? s.first : s.second) = {std::int32_t(t), i};
      ++s.count;
    }
  }
  std::vector<std::array<Neighbour, 3>> out(mesh.triangles.size());
  for (const auto& [key, s] : edges) {
    if (s.count != 2) continue;
    out[std::size_t(s.first.triangle)][std::size_t(s.first.edge)] = s.second;
    out[std::size_t(s.second.triangle)][std::size_t(s.second.edge)] = s.first;
  }
  return out;
}

// Every primitive the scene draws, in draw order and bounded: the triangles of each clipped fan,
// or in wireframe each clipped polygon's edges. visit(shape, flat colour) with a TriangleShape or
// a LineShape; `colours` asks for lit corner colours (pass 2 only).
class Primitives {
 public:
  Primitives(const Scene& scene, const DrawList& list, int subpixel_bits)
      : list_(list), subpixel_bits_(subpixel_bits) {
    if (list.lighting && !list.wireframe) light_.emplace(scene);
  }

  template <class Visit>
  void ForEach(bool colours, Visit&& visit) const {
    for (std::size_t d = 0; d < list_.draws.size(); ++d) {
      const DrawMesh& mesh = list_.meshes[list_.draws[d].mesh];
      const std::vector<BoundedVertex> vertices = Vertices(d);
      const bool lit = mesh.shading != Shading::kUnlit && light_;
      std::vector<std::array<glm::dvec3, 3>> corner;
      if (lit && colours) corner = light_->CornerColours(d);
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        std::array<BoundedVertex, 3> v{vertices[tri[0]], vertices[tri[1]], vertices[tri[2]]};
        if (!corner.empty()) {
          for (int k = 0; k < 3; ++k) v[k].colour = corner[t][k];
        }
        const WindowPolygon polygon = ClipToWindow(v[0], v[1], v[2], list_.width, list_.height, subpixel_bits_);
        if (list_.wireframe) {
          for (int i = 0; i < polygon.size; ++i) {
            visit(LineShape(polygon.v[i], polygon.v[(i + 1) % polygon.size], polygon.edge_from_clipping[i]),
                  mesh.colours[t]);
          }
          continue;
        }
        for (int i = 2; i < polygon.size; ++i) {
          visit(TriangleShape(polygon.v[0], polygon.v[i - 1], polygon.v[i], lit), mesh.colours[t]);
        }
      }
    }
  }

  // Pass 1: the nearest surface certain to be written at each pixel, and the farthest depth it
  // may have there. A centre inside a triangle but within reach of one edge it shares with
  // another triangle of the mesh is covered by one of the two whichever way the edge moves (the
  // vertices are the same for both, and the spec's tie rule leaves no gap between them): certain,
  // with the farther of the two depths.
  void Occlude(FrameJudge& judge) const {
    const std::uint32_t w = list_.width, h = list_.height;
    if (list_.wireframe) {
      ForEach(false, [&](const auto& shape, Rgb8) {
        Scan(shape, shape.Box(w, h), [&](int x, int y, glm::dvec2 p, Coverage c) {
          if (c == Coverage::kIn) judge.Occlude(x, y, shape.Depth(p));
        });
      });
      return;
    }
    std::vector<std::optional<std::vector<std::array<Neighbour, 3>>>> neighbours(list_.meshes.size());
    std::vector<WindowVertex> window;
    std::vector<char> inside;
    for (std::size_t d = 0; d < list_.draws.size(); ++d) {
      const DrawMesh& mesh = list_.meshes[list_.draws[d].mesh];
      const std::vector<BoundedVertex> vertices = Vertices(d);
      auto& nb = neighbours[list_.draws[d].mesh];
      if (!nb) nb = MeshNeighbours(mesh);
      window.assign(vertices.size(), WindowVertex{});
      inside.assign(vertices.size(), 0);
      for (std::size_t i = 0; i < vertices.size(); ++i) {
        inside[i] = InsideViewVolume(vertices[i]);
        if (inside[i]) window[i] = MapToWindow(vertices[i], w, h, subpixel_bits_);
      }
      for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
        const auto& tri = mesh.triangles[t];
        if (!inside[tri[0]] || !inside[tri[1]] || !inside[tri[2]]) {
          const WindowPolygon polygon = ClipToWindow(vertices[tri[0]], vertices[tri[1]], vertices[tri[2]], w, h, subpixel_bits_);
          for (int i = 2; i < polygon.size; ++i) {
            const TriangleShape shape(polygon.v[0], polygon.v[i - 1], polygon.v[i], false);
            Scan(shape, shape.Box(w, h), [&](int x, int y, glm::dvec2 p, Coverage c) {
              if (c == Coverage::kIn) judge.Occlude(x, y, shape.Depth(p));
            });
          }
          continue;
        }
        const TriangleShape shape(window[tri[0]], window[tri[1]], window[tri[2]], false);
        std::array<std::optional<TriangleShape>, 3> across;
        Scan(shape, shape.Box(w, h), [&](int x, int y, glm::dvec2 p, Coverage c) {
          if (c == Coverage::kIn) {
            judge.Occlude(x, y, shape.Depth(p));
            return;
          }
          if (shape.Degenerate()) return;
          const std::array<double, 3> dt = shape.EdgeDistances(p);
          int near = -1;
          for (int j = 0; j < 3; ++j) {
            if (dt[j] < 0) return;  // outside: the neighbour decides from its side
            if (dt[j] <= shape.EdgeRadius(j)) {
              if (near >= 0) return;  // near a corner
              near = j;
            }
          }
          if (near < 0) return;
          const Neighbour n = (*nb)[t][std::size_t(near)];
          if (n.triangle < 0) return;
          const auto& nt = mesh.triangles[std::size_t(n.triangle)];
          if (!inside[nt[0]] || !inside[nt[1]] || !inside[nt[2]]) return;
          if (!across[near]) across[near].emplace(window[nt[0]], window[nt[1]], window[nt[2]], false);
          const TriangleShape& other = *across[near];
          if (other.Degenerate()) return;
          // The other triangle must lie across the shared edge, not folded over this one.
          const double r = std::max(shape.radius(), other.radius());
          if (shape.EdgeDistances(window[nt[std::size_t((n.edge + 2) % 3)]].xy)[near] >= -r) return;
          const std::array<double, 3> dn = other.EdgeDistances(p);
          for (int j = 0; j < 3; ++j) {
            if (j != n.edge && dn[j] <= other.EdgeRadius(j)) return;
          }
          const std::array<double, 2> a = shape.Depth(p), b = other.Depth(p);
          judge.Occlude(x, y, {std::min(a[0], b[0]), std::max(a[1], b[1])});
        });
      }
    }
  }

 private:
  std::vector<BoundedVertex> Vertices(std::size_t d) const {
    return BoundVertices(list_.draws[d].F, list_.meshes[list_.draws[d].mesh].positions);
  }

  const DrawList& list_;
  int subpixel_bits_;
  std::optional<ExactLight> light_;
};

// Pass 2 at one pixel only, gathering what each surface that may show there allows.
std::vector<ColourRange> AllowedAt(const Primitives& primitives, FrameJudge& judge, int x, int y) {
  std::vector<ColourRange> allowed;
  primitives.ForEach(true, [&](const auto& shape, Rgb8 flat) {
    const PixelBox box = shape.Box(judge.width(), judge.height());
    if (x < box.x0 || x > box.x1 || y < box.y0 || y > box.y1) return;
    Scan(shape, PixelBox{x, y, x, y}, [&](int, int, glm::dvec2 p, Coverage) {
      if (judge.MayShow(x, y, shape.Depth(p))) allowed.push_back(shape.Colour(p, flat));
    });
  });
  if (judge.BackgroundMayShow(x, y)) allowed.push_back(ColourRange::Exactly(judge.background()));
  return allowed;
}

}  // namespace

Verification VerifyImage(const Scene& scene, const DrawList& list, const Image& image, const VerifyOptions& options) {
  CheckInputs(scene, list, image, options);
  const Primitives primitives(scene, list, options.subpixel_bits);
  FrameJudge judge(image, list.background, list.reversed_z);
  const std::uint32_t w = image.width, h = image.height;
  primitives.Occlude(judge);
  // Pass 2: every surface that may cover a pixel and is not surely behind that one may show.
  primitives.ForEach(true, [&](const auto& shape, Rgb8 flat) {
    Scan(shape, shape.Box(w, h), [&](int x, int y, glm::dvec2 p, Coverage) {
      if (judge.MayShow(x, y, shape.Depth(p))) judge.Offer(x, y, shape.Colour(p, flat));
    });
  });
  Verification result = judge.Finish(options.subpixel_bits);
  for (std::optional<Violation>* v : {&result.worst, &result.first}) {
    if (*v) (*v)->allowed = AllowedAt(primitives, judge, int((*v)->x), int((*v)->y));
  }
  return result;
}

}  // namespace twinraster::verify
