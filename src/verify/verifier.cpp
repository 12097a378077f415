#include "verify/verifier.hpp"

#include "truth/truth_renderer.hpp"
#include "verify/coverage_shapes.hpp"
#include "verify/frame_shared.hpp"
#include "verify/pixel_judge.hpp"
#include "verify/scan.hpp"
#include "verify/sole_surfaces.hpp"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <future>
#include <limits>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <type_traits>

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

// A draw that reaches a band: the union of its primitives' boxes there and of their depth ranges
// (NaN when any range is), so that one test can skip a draw only when it would skip each of them.
struct DrawReach {
  std::size_t draw = 0;
  PixelBox box;
  std::array<double, 2> range{std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

  void Add(const PixelBox& b, std::array<double, 2> r) {
    box = box.Empty() ? b
                      : PixelBox{std::min(box.x0, b.x0), std::min(box.y0, b.y0), std::max(box.x1, b.x1),
                                 std::max(box.y1, b.y1)};
    if (std::isnan(r[0]) || std::isnan(r[1]) || std::isnan(range[0])) {
      range = {std::nan(""), std::nan("")};
      return;
    }
    range = {std::min(range[0], r[0]), std::max(range[1], r[1])};
  }
  bool Contains(int x, int y) const { return x >= box.x0 && x <= box.x1 && y >= box.y0 && y <= box.y1; }
};

// A draw's vertices bounded in clip space and, for those inside the view volume, mapped to the
// framebuffer once for all the triangles that share them.
struct DrawGeometry {
  std::vector<BoundedVertex> clip;
  std::vector<WindowVertex> window;
  std::vector<char> inside;
};

// A draw prepared once for all the bands: its geometry, and the extent of the rows its triangles
// may reach (none when unknown: the draw reaches every band).
struct PreparedDraw {
  DrawGeometry g;
  std::optional<std::array<double, 2>> rows;
};

// Every primitive the scene draws, in draw order and bounded: the triangles of each clipped fan,
// or in wireframe each clipped polygon's edges.
class Primitives {
 public:
  Primitives(const FrameShared& shared, const DrawList& list, const VerifyOptions& options)
      : list_(list),
        shared_(shared),
        subpixel_bits_(options.subpixel_bits),
        fast_(options.fast_paths),
        line_rules_(options.strict_lines ? LineRules::kStrict : LineRules::kNotStrict) {}

  // visit(shape, flat colour, triangle index, whether unclipped) for each primitive of draw d, with
  // a TriangleShape or a LineShape; `colours` asks for lit corner colours (pass 2 only).
  template <class Visit>
  void ForEachInDraw(std::size_t d, bool colours, DrawGeometry& g, Visit&& visit) const {
    Prepare(d, g);
    VisitDraw(d, colours, g, visit);
  }

  // ForEachInDraw once Prepare(d, g) has run.
  template <class Visit>
  void VisitDraw(std::size_t d, bool colours, const DrawGeometry& g, Visit&& visit) const {
    const DrawMesh& mesh = list_.meshes[list_.draws[d].mesh];
    const bool lit = mesh.smooth() && shared_.lit();  // lit or vertex-coloured: corner colours vary
    FrameShared::Corners scratch;
    const FrameShared::Corners& corner = lit && colours ? shared_.CornerColours(d, scratch) : scratch;
    for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
      const auto& tri = mesh.triangles[t];
      if (!list_.wireframe && g.inside[tri[0]] && g.inside[tri[1]] && g.inside[tri[2]]) {
        std::array<WindowVertex, 3> v{g.window[tri[0]], g.window[tri[1]], g.window[tri[2]]};
        if (!corner.empty()) {
          for (std::size_t k = 0; k < 3; ++k) v[k].colour = corner[t][k];
        }
        visit(TriangleShape(v[0], v[1], v[2], lit), mesh.colours[t], t, true);
        continue;
      }
      std::array<BoundedVertex, 3> v{g.clip[tri[0]], g.clip[tri[1]], g.clip[tri[2]]};
      if (!corner.empty()) {
        for (std::size_t k = 0; k < 3; ++k) v[k].colour = corner[t][k];
      }
      const WindowPolygon polygon = ClipToWindow(v[0], v[1], v[2], list_.width, list_.height, subpixel_bits_,
                                                 list_.wireframe ? ClipVolume::kDepth : ClipVolume::kView);
      if (list_.wireframe) {
        VisitLines(polygon, mesh.colours[t], t, visit);
        if (g.inside[tri[0]] && g.inside[tri[1]] && g.inside[tri[2]]) continue;  // no clipping, no new edge
        // An implementation that clips by the whole view volume may also draw the edges that clipping
        // makes along the canvas's border: they may show, never must.
        const WindowPolygon view = ClipToWindow(v[0], v[1], v[2], list_.width, list_.height, subpixel_bits_);
        for (std::size_t i = 0; i < view.size; ++i) {
          if (view.edge_from_clipping[i]) {
            visit(LineShape(view.v[i], view.v[(i + 1) % view.size], true, line_rules_, list_.width, list_.height),
                  mesh.colours[t], t, false);
          }
        }
        continue;
      }
      for (std::size_t i = 2; i < polygon.size; ++i) {
        visit(TriangleShape(polygon.v[0], polygon.v[i - 1], polygon.v[i], lit), mesh.colours[t], t, false);
      }
    }
  }

  template <class Visit>
  void VisitLines(const WindowPolygon& polygon, Rgb8 colour, std::size_t t, Visit&& visit) const {
    for (std::size_t i = 0; i < polygon.size; ++i) {
      visit(LineShape(polygon.v[i], polygon.v[(i + 1) % polygon.size], polygon.edge_from_clipping[i], line_rules_,
                      list_.width, list_.height),
            colour, t, false);
    }
  }

  // Pass 1 for draw d, `prepared` by PrepareShared: the nearest surface certain to be written at
  // each pixel, and the farthest depth it may have there. A centre inside a triangle but within reach
  // of one edge it shares with another triangle of the mesh is covered by one of the two whichever way
  // the edge moves (the vertices are the same for both, and the spec's tie rule leaves no gap between
  // them): certain, with the farther of the two depths.
  // Appends the draw to `reaching` if it reaches the band (pass 2 and AllowedAt need no others).
  // `since_refresh` counts the triangles since the judge's tiles were last refreshed.
  void OccludeDraw(FrameJudge& judge, std::size_t d, const PreparedDraw& prepared, std::vector<DrawReach>& reaching,
                   std::size_t& since_refresh) {
    const std::uint32_t w = list_.width, h = list_.height;
    const DrawMesh& mesh = list_.meshes[list_.draws[d].mesh];
    since_refresh += mesh.triangles.size();
    const PixelBox rows = judge.Clip({0, 0, 0, int(h) - 1});
    const auto& extent = prepared.rows;
    if (fast_ && extent && ((*extent)[1] < rows.y0 + 0.5 || (*extent)[0] > rows.y1 + 0.5)) return;
    const DrawGeometry& g = prepared.g;
    DrawReach reach;
    reach.draw = d;
    const auto occlude = [&](const auto& shape, Rgb8, std::size_t t, bool unclipped) {
      if (fast_ && judge.TilesWorthRefreshing()) judge.RefreshTiles(), since_refresh = 0;
      const PixelBox box = judge.Clip(shape.Box(w, h));
      if (box.Empty()) return;
      const std::array<double, 2> range = shape.DepthRange();
      reach.Add(box, range);
      if (!judge.CouldMatter(box, range, false)) return;
      if constexpr (std::is_same_v<std::decay_t<decltype(shape)>, TriangleShape>) {
        if (unclipped) {
          OccludeWithNeighbours(judge, shape, box, TileCull<TriangleShape>{judge, shape, box, range, false, fast_},
                                mesh, shared_.Neighbours(list_.draws[d].mesh), t, g);
          return;
        }
      }
      const auto depth = [&](glm::dvec2 p) { return shape.Depth(p); };
      ScanRuns(
          shape, box, TileCull<std::decay_t<decltype(shape)>>{judge, shape, box, range, false, fast_},
          [&](int x, int y, glm::dvec2 p, Coverage c) {
            if (c == Coverage::kIn) judge.Occlude(x, y, shape.Depth(p));
          },
          [&](int y, int x0, int x1) { judge.OccludeRun(y, x0, x1, depth); });
    };
    VisitDraw(d, false, g, occlude);
    if (!reach.box.Empty()) reaching.push_back(reach);
    if (since_refresh >= 1024) judge.RefreshTiles(), since_refresh = 0;
  }

  // Draw d prepared for every band's pass 1: its geometry and the rows its triangles may reach.
  void PrepareShared(std::size_t d, PreparedDraw& p) const {
    Prepare(d, p.g);
    p.rows = RowExtent(p.g);
  }

  // A draw's vertices bounded and, where inside the view volume, mapped to the framebuffer.
  void Prepare(std::size_t d, DrawGeometry& g) const {
    const DrawCall& draw = list_.draws[d];
    BoundVertices(draw.F, list_.meshes[draw.mesh].positions, g.clip);
    g.window.resize(g.clip.size());
    g.inside.assign(g.clip.size(), 0);
    for (std::size_t i = 0; i < g.clip.size(); ++i) {
      g.inside[i] = InsideViewVolume(g.clip[i]);
      if (g.inside[i]) g.window[i] = MapToWindow(g.clip[i], list_.width, list_.height, subpixel_bits_);
    }
  }

 private:
  // The extent in y of the rows the prepared draw's triangles may reach (a box's rows are those
  // whose centres y + 0.5 lie in it): each triangle's Box lies within its draw's vertices' extent
  // widened by the largest radius any of them has. None for wireframes and draws that clipping
  // cuts, which are never culled by rows.
  std::optional<std::array<double, 2>> RowExtent(const DrawGeometry& g) const {
    if (list_.wireframe) return std::nullopt;
    double y0 = std::numeric_limits<double>::infinity(), y1 = -y0, error = 0;
    for (std::size_t i = 0; i < g.clip.size(); ++i) {
      if (!g.inside[i]) return std::nullopt;
      y0 = std::min(y0, g.window[i].xy.y), y1 = std::max(y1, g.window[i].xy.y);
      error = std::max(error, g.window[i].xy_error);
    }
    const double radius = std::sqrt(2.0) * error;  // as TriangleShape's, so never smaller than one
    y0 -= radius, y1 += radius;
    if (!std::isfinite(y0) || !std::isfinite(y1)) return std::nullopt;
    return std::array<double, 2>{y0, y1};
  }

  static void OccludeWithNeighbours(FrameJudge& judge, const TriangleShape& shape, const PixelBox& box,
                                    const TileCull<TriangleShape>& keep, const DrawMesh& mesh,
                                    const std::vector<std::array<Neighbour, 3>>& nb, std::size_t t,
                                    const DrawGeometry& g) {
    std::array<std::optional<TriangleShape>, 3> across;
    const auto depth = [&](glm::dvec2 p) { return shape.Depth(p); };
    const auto inside = [&](int y, int x0, int x1) { judge.OccludeRun(y, x0, x1, depth); };
    ScanRuns(
        shape, box, keep,
        [&](int x, int y, glm::dvec2 p, Coverage c) {
          if (c == Coverage::kIn) {
            judge.Occlude(x, y, shape.Depth(p));
            return;
          }
          if (shape.Degenerate()) return;
          const std::array<double, 3> dt = shape.EdgeDistances(p);
          std::size_t near = 3;  // the one edge it lies within reach of
          for (std::size_t j = 0; j < 3; ++j) {
            if (dt[j] < 0) return;  // outside: the neighbour decides from its side
            if (dt[j] <= shape.EdgeRadius(int(j))) {
              if (near < 3) return;  // near a corner
              near = j;
            }
          }
          if (near == 3) return;
          const Neighbour n = nb[t][near];
          if (n.triangle < 0) return;
          const auto& nt = mesh.triangles[std::size_t(n.triangle)];
          if (!g.inside[nt[0]] || !g.inside[nt[1]] || !g.inside[nt[2]]) return;
          if (!across[near]) across[near].emplace(g.window[nt[0]], g.window[nt[1]], g.window[nt[2]], false);
          const TriangleShape& other = *across[near];
          if (other.Degenerate()) return;
          // The other triangle must lie across the shared edge, not folded over this one.
          const double r = std::max(shape.radius(), other.radius());
          if (shape.EdgeDistances(g.window[nt[std::size_t((n.edge + 2) % 3)]].xy)[near] >= -r) return;
          const std::array<double, 3> dn = other.EdgeDistances(p);
          for (std::size_t j = 0; j < 3; ++j) {
            if (int(j) != n.edge && dn[j] <= other.EdgeRadius(int(j))) return;
          }
          const std::array<double, 2> a = shape.Depth(p), b = other.Depth(p);
          judge.Occlude(x, y, {std::min(a[0], b[0]), std::max(a[1], b[1])});
        },
        inside);
  }

  const DrawList& list_;
  const FrameShared& shared_;
  int subpixel_bits_;
  bool fast_;  // VerifyOptions::fast_paths
  LineRules line_rules_;
};

// One band of rows: its own primitives' state, its judge, and the draws that reach it.
struct Band {
  Band(const FrameShared& shared, const DrawList& list, const Image& image, const VerifyOptions& options, int row0,
       int row1)
      : primitives(shared, list, options),
        judge(image, list.background, list.reversed_z, row0, row1),
        sole(judge),
        fast(options.fast_paths) {}
  Primitives primitives;
  FrameJudge judge;
  SoleSurfaces sole;  // pass 2's tiles one surface settles (a fast path)
  std::uint64_t shapes_offered = 0;
  std::vector<DrawReach> reaching;
  Verification counts;
  bool fast = true;
};

// Pass 2 at one pixel of the band only, gathering what each surface that may show there allows:
// only draws whose boxes in the band hold the pixel can.
std::vector<ColourRange> AllowedAt(const Band& band, int x, int y) {
  const FrameJudge& judge = band.judge;
  std::vector<ColourRange> allowed;
  DrawGeometry g;
  for (const DrawReach& reach : band.reaching) {
    if (!reach.Contains(x, y)) continue;
    band.primitives.ForEachInDraw(reach.draw, true, g, [&](const auto& shape, Rgb8 flat, std::size_t, bool) {
      const PixelBox box = shape.Box(judge.width(), judge.height());
      if (x < box.x0 || x > box.x1 || y < box.y0 || y > box.y1) return;
      const Coverage c = shape.Covers(glm::dvec2(x + 0.5, y + 0.5));
      if (c == Coverage::kOut) return;
      const glm::dvec2 p(x + 0.5, y + 0.5);
      const ColourRange colours = shape.Colour(p, flat);
      if (judge.MayShow(x, y, shape.Depth(p)) && std::find(allowed.begin(), allowed.end(), colours) == allowed.end()) {
        allowed.push_back(colours);
      }
    });
  }
  if (judge.BackgroundMayShow(x, y)) allowed.push_back(ColourRange::Exactly(judge.background()));
  return allowed;
}

// What the bands share in pass 1: each draw is prepared once for the frame, a chunk of draws at a
// time, by whichever band first reaches the chunk before it, into a ring of chunks that every band
// then reads in draw order. Whole chunks, so that no two cores write the same cache lines. A band
// ahead of the others prepares for them; one behind finds its draws ready. A chunk's slot is reused
// only once every band has finished with the chunk it held.
class SharedPass1 {
 public:
  static constexpr std::size_t kChunk = 256, kSlots = 16;        // draws
  static constexpr std::size_t kBudget = std::size_t{64} << 20;  // bytes of geometry the ring may hold

  // Whether the ring of `list`'s draws fits the budget; if not, each band prepares its own draws.
  static bool Fits(const DrawList& list) {
    std::size_t vertices = 0;
    for (const DrawMesh& mesh : list.meshes) vertices = std::max(vertices, mesh.positions.size());
    const std::size_t per_vertex = sizeof(BoundedVertex) + sizeof(WindowVertex) + 1;
    return vertices <= kBudget / per_vertex / (kChunk * kSlots);
  }

  SharedPass1(std::size_t bands, std::size_t draws) : bands_(bands), draws_(draws), slots_(kSlots) {
    for (std::size_t s = 0; s < kSlots; ++s) {
      slots_[s].draws.resize(kChunk);
      slots_[s].writable.store(s);
    }
  }

  // Draw d, prepared. The band asking prepares (with `primitives`) the chunks up to the one after
  // d's that no band has claimed yet, so that the next chunk is usually ready when it is reached.
  const PreparedDraw& Get(std::size_t d, const Primitives& primitives) {
    for (std::size_t c = next_.load(); c <= d / kChunk + 1; c = next_.load()) {
      if (next_.compare_exchange_weak(c, c + 1)) Prepare(c, primitives);
    }
    Slot& slot = slots_[d / kChunk % kSlots];
    WaitFor([&] { return slot.ready.load(std::memory_order_acquire) == d / kChunk + 1; });
    return slot.draws[d % kChunk];
  }

  // One band is done with `chunk` (called after its last draw, or the frame's).
  void Finished(std::size_t chunk) {
    Slot& slot = slots_[chunk % kSlots];
    if (slot.finished.fetch_add(1, std::memory_order_acq_rel) + 1 == bands_) {
      slot.finished.store(0, std::memory_order_relaxed);  // before any band can finish the next chunk
      slot.writable.store(chunk + kSlots, std::memory_order_release);
    }
  }

  void Fail() { failed_ = true; }  // a band threw: the others stop rather than wait for it

 private:
  struct Slot {
    std::vector<PreparedDraw> draws;
    std::atomic<std::size_t> ready{0};     // the chunk held + 1 once prepared
    std::atomic<std::size_t> writable{0};  // the chunk that may be written here
    std::atomic<std::size_t> finished{0};  // bands done with the chunk held
  };

  void Prepare(std::size_t chunk, const Primitives& primitives) {
    if (chunk * kChunk >= draws_) return;
    Slot& slot = slots_[chunk % kSlots];
    WaitFor([&] { return slot.writable.load(std::memory_order_acquire) == chunk; });
    for (std::size_t d = chunk * kChunk; d < std::min(draws_, (chunk + 1) * kChunk); ++d) {
      primitives.PrepareShared(d, slot.draws[d % kChunk]);
    }
    slot.ready.store(chunk + 1, std::memory_order_release);
  }

  // Yields while waiting: the band waited for may need this core.
  template <class Done>
  void WaitFor(Done&& done) const {
    while (!done()) {
      if (failed_) throw std::runtime_error("another band of the frame failed");
      std::this_thread::yield();
    }
  }

  std::size_t bands_, draws_;
  std::vector<Slot> slots_;
  std::atomic<std::size_t> next_{0};  // the first chunk no band has claimed
  std::atomic<bool> failed_{false};
};

// Pass 1 of one band, with the draws prepared through `shared`, or by the band itself when null.
void OccludeShared(Band& band, SharedPass1* shared, std::size_t draws) {
  std::size_t since_refresh = 0;
  if (!shared) {
    PreparedDraw own;
    for (std::size_t d = 0; d < draws; ++d) {
      band.primitives.PrepareShared(d, own);
      band.primitives.OccludeDraw(band.judge, d, own, band.reaching, since_refresh);
    }
    band.judge.RefreshTiles();
    return;
  }
  for (std::size_t d = 0; d < draws; ++d) {
    band.primitives.OccludeDraw(band.judge, d, shared->Get(d, band.primitives), band.reaching, since_refresh);
    if ((d + 1) % SharedPass1::kChunk == 0 || d + 1 == draws) shared->Finished(d / SharedPass1::kChunk);
  }
  band.judge.RefreshTiles();
}

// One band of rows judged whole once pass 1 has run: pass 2, then each pixel's class into `pixels`
// (the whole frame's; the band writes only its rows) and the band's counts.
void JudgeBand(Band& band, const Image& image, std::vector<PixelClass>& pixels, std::vector<Reach>& reaches) {
  FrameJudge& judge = band.judge;
  const std::uint32_t w = image.width, h = image.height;
  // Pass 2: every surface that may cover a pixel and is not surely behind that one may show.
  const auto offer = [&](const auto& shape, Rgb8 flat, std::size_t, bool) {
    const PixelBox box = judge.Clip(shape.Box(w, h));
    const std::array<double, 2> range = shape.DepthRange();
    if (!judge.CouldMatter(box, range, true)) return;
    constexpr bool kLine = std::is_same_v<std::decay_t<decltype(shape)>, LineShape>;
    const TileCull<std::decay_t<decltype(shape)>> cull{judge, shape, box, range, true, band.fast};
    const std::uint64_t serial = ++band.shapes_offered;
    const auto keep = [&](int y, int x0, int x1) {
      if (!band.fast) return true;
      if (band.sole.HeldBy(judge.TileOf(x0, y), serial)) return false;
      return cull(y, x0, x1) && band.sole.Keep(shape, flat, box, x0, y, serial);
    };
    const auto depth = [&](glm::dvec2 p) { return shape.Depth(p); };
    const auto colour = [&](glm::dvec2 p) { return shape.Colour(p, flat); };
    ScanRuns(
        shape, box, keep,
        [&](int x, int y, glm::dvec2 p, Coverage c) {
          if (judge.MayShow(x, y, shape.Depth(p)))
            judge.Offer(x, y, shape.Colour(p, flat), kLine && c == Coverage::kIn);
        },
        [&](int y, int x0, int x1) { judge.OfferRun(y, x0, x1, depth, colour, kLine); });
  };
  DrawGeometry g;
  for (const DrawReach& reach : band.reaching) {
    if (!band.fast || judge.CouldMatter(reach.box, reach.range, true))
      band.primitives.ForEachInDraw(reach.draw, true, g, offer);
  }
  if (!reaches.empty()) judge.WriteReach(reaches);  // before Finish offers the background
  FrameJudge::SettledRun settled;
  if (band.fast)
    settled = [&](int y, int x0, int x1, ColourRange* colours) { return band.sole.Settled(y, x0, x1, colours); };
  judge.Finish(band.counts, pixels, settled);
}

// The bands' counts summed; the first violation is the first band's, the worst the first of the
// largest distance. The colours allowed are gathered for those two pixels only.
void Merge(const std::vector<std::unique_ptr<Band>>& bands, Verification& result) {
  const Band* first = nullptr;
  const Band* worst = nullptr;
  for (const auto& band : bands) {  // top to bottom
    const Verification& b = band->counts;
    result.certain += b.certain, result.uncertain += b.uncertain, result.violations += b.violations;
    result.covered += b.covered, result.uncertain_shared_edges += b.uncertain_shared_edges;
    result.background_excluded += b.background_excluded;
    if (!result.first && b.first) result.first = b.first, first = band.get();
    if (b.worst && (!result.worst || b.worst->distance > result.worst->distance))
      result.worst = b.worst, worst = band.get();
  }
  if (first) result.first->allowed = AllowedAt(*first, int(result.first->x), int(result.first->y));
  if (worst) {
    const bool same = first && result.first->x == result.worst->x && result.first->y == result.worst->y;
    result.worst->allowed =
        same ? result.first->allowed : AllowedAt(*worst, int(result.worst->x), int(result.worst->y));
  }
}

}  // namespace

Verification VerifyImage(const Scene& scene, const DrawList& list, const Image& image, const VerifyOptions& options) {
  CheckInputs(scene, list, image, options);
  Verification result;
  result.width = image.width, result.height = image.height, result.options = options;
  result.pixels.resize(std::size_t{image.width} * image.height);
  if (options.reach) result.reach.resize(result.pixels.size());
  // Bands of whole 16-row tiles, one per hardware thread: each sees every primitive and judges
  // its own pixels, so they share only the read-only inputs, what each draw's light and mesh make
  // once for all (FrameShared), the draws prepared for pass 1 (SharedPass1) and the pixel classes.
  const FrameShared frame(scene, list);
  const int rows = int(image.height);
  const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, unsigned((rows + 15) / 16)));
  const int band_rows = ((rows + threads - 1) / threads + 15) / 16 * 16;
  std::vector<std::unique_ptr<Band>> bands(std::size_t((rows + band_rows - 1) / band_rows));
  std::optional<SharedPass1> shared;
  if (SharedPass1::Fits(list)) shared.emplace(bands.size(), list.draws.size());
  const auto judge_band = [&](std::size_t b) {
    const int row0 = int(b) * band_rows, row1 = std::min(rows, row0 + band_rows);
    try {
      bands[b] = std::make_unique<Band>(frame, list, image, options, row0, row1);  // its set-up on its thread
      OccludeShared(*bands[b], shared ? &*shared : nullptr, list.draws.size());
    } catch (...) {
      if (shared) shared->Fail();  // the other bands must not wait for this one
      throw;
    }
    JudgeBand(*bands[b], image, result.pixels, result.reach);
  };
  // The first band on this thread, each other on one of its own. A band that throws, or one that
  // gets no thread, fails the others; the futures wait for their threads when unwinding.
  std::vector<std::future<void>> running;
  running.reserve(bands.size());  // so that only std::async can throw below
  for (std::size_t b = 1; b < bands.size(); ++b) {
    try {
      running.push_back(std::async(std::launch::async, judge_band, b));
    } catch (...) {
      if (shared) shared->Fail();
      throw;
    }
  }
  judge_band(0);
  for (auto& r : running) r.get();  // rethrows a band's exception
  Merge(bands, result);
  return result;
}

}  // namespace twinraster::verify
