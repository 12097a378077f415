#include "verify/verifier.hpp"

#include "verify/band.hpp"
#include "verify/pass1_ring.hpp"
#include "verify/scan.hpp"
#include "verify/work_estimate.hpp"

#include <algorithm>
#include <future>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
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

// Pass 1 for draw d of the band, `prepared` by PrepareForPass1: the nearest surface certain to be
// written at each pixel, and the farthest depth it may have there. Appends the draw to the band's
// `reaching` if it reaches the band (pass 2 and AllowedAt need no others). `since_refresh` counts
// the triangles since the judge's tiles were last refreshed.
void OccludeDraw(Band& band, std::size_t d, const PreparedDraw& prepared, std::size_t& since_refresh) {
  FrameJudge& judge = band.judge;
  const std::uint32_t w = band.list.width, h = band.list.height;
  const std::size_t mesh_index = band.list.draws[d].mesh;
  const DrawMesh& mesh = band.list.meshes[mesh_index];
  since_refresh += mesh.triangles.size();
  const PixelBox rows = judge.Clip({0, 0, 0, int(h) - 1});
  const auto& extent = prepared.rows;
  if (band.fast && extent && ((*extent)[1] < rows.y0 + 0.5 || (*extent)[0] > rows.y1 + 0.5)) return;
  DrawReach reach;
  reach.draw = d;
  const auto occlude = [&](const auto& shape, Rgb8, std::size_t t, bool unclipped) {
    using Shape = std::decay_t<decltype(shape)>;
    if (band.fast && judge.TilesWorthRefreshing()) judge.RefreshTiles(), since_refresh = 0;
    const PixelBox box = judge.Clip(shape.Box(w, h));
    if (box.Empty()) return;
    const std::array<double, 2> range = shape.DepthRange();
    reach.Add(box, range);
    if (!judge.CouldMatter(box, range, false)) return;
    // An unclipped triangle also covers, with its neighbour, the centres near their shared edge.
    const std::vector<std::array<Neighbour, 3>>* neighbours = nullptr;
    if constexpr (std::is_same_v<Shape, TriangleShape>) {
      if (unclipped) neighbours = &band.shared.Neighbours(mesh_index);
    }
    AcrossEdges across;
    const auto depth = [&](glm::dvec2 p) { return shape.Depth(p); };
    ScanRuns(
        shape, box, TileCull<Shape>{judge, shape, box, range, false, band.fast},
        [&](int x, int y, glm::dvec2 p, Coverage c) {
          if (c == Coverage::kIn) {
            judge.Occlude(x, y, shape.Depth(p));
          } else if constexpr (std::is_same_v<Shape, TriangleShape>) {
            if (!neighbours) return;
            if (const auto shared = DepthAcrossSharedEdge(shape, p, mesh, *neighbours, t, prepared.g, across))
              judge.Occlude(x, y, *shared);
          }
        },
        [&](int y, int x0, int x1) { judge.OccludeRun(y, x0, x1, depth); });
  };
  band.primitives.VisitDraw(d, false, prepared.g, occlude);
  if (!reach.box.Empty()) band.reaching.push_back(reach);
  if (since_refresh >= 1024) judge.RefreshTiles(), since_refresh = 0;
}

// Pass 1 of one band, with the draws prepared by `ring`, or by the band itself when null.
void OccludeBand(Band& band, Pass1Ring* ring, std::size_t draws) {
  std::size_t since_refresh = 0;
  if (!ring) {
    PreparedDraw own;
    for (std::size_t d = 0; d < draws; ++d) {
      band.primitives.PrepareForPass1(d, own);
      OccludeDraw(band, d, own, since_refresh);
    }
    band.judge.RefreshTiles();
    return;
  }
  for (std::size_t d = 0; d < draws; ++d) {
    OccludeDraw(band, d, ring->Get(d, band.primitives), since_refresh);
    if ((d + 1) % Pass1Ring::kChunk == 0 || d + 1 == draws) ring->Finished(d / Pass1Ring::kChunk);
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

}  // namespace

Verification VerifyImage(const Scene& scene, const DrawList& list, const Image& image, const VerifyOptions& options) {
  CheckInputs(scene, list, image, options);
  Verification result;
  result.width = image.width, result.height = image.height, result.options = options;
  result.pixels.resize(std::size_t{image.width} * image.height);
  if (options.reach) result.reach.resize(result.pixels.size());
  result.work = {EstimatePixelTests(list, options.pixel_test_budget), options.pixel_test_budget};
  if (result.work.Exceeded()) {  // nothing is judged, so nothing is certain
    std::fill(result.pixels.begin(), result.pixels.end(), PixelClass::kUncertain);
    std::fill(result.reach.begin(), result.reach.end(), Reach::kMaybe);
    result.uncertain = result.covered = result.pixels.size();
    return result;
  }
  // Bands of whole 16-row tiles, one per hardware thread: each sees every primitive and judges
  // its own pixels, so they share only the read-only inputs, what each draw's light and mesh make
  // once for all (FrameShared), the draws prepared for pass 1 (Pass1Ring) and the pixel classes.
  const FrameShared frame(scene, list);
  const int rows = int(image.height);
  const int band_rows = BandRows(rows);
  std::vector<std::unique_ptr<Band>> bands(std::size_t((rows + band_rows - 1) / band_rows));
  std::optional<Pass1Ring> ring;
  if (Pass1Ring::Fits(list)) ring.emplace(bands.size(), list.draws.size());
  const auto judge_band = [&](std::size_t b) {
    const int row0 = int(b) * band_rows, row1 = std::min(rows, row0 + band_rows);
    try {
      bands[b] = std::make_unique<Band>(frame, list, image, options, row0, row1);  // its set-up on its thread
      OccludeBand(*bands[b], ring ? &*ring : nullptr, list.draws.size());
    } catch (...) {
      if (ring) ring->Fail();  // the other bands must not wait for this one
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
      if (ring) ring->Fail();
      throw;
    }
  }
  judge_band(0);
  for (auto& r : running) r.get();  // rethrows a band's exception
  MergeBands(bands, result);
  return result;
}

}  // namespace twinraster::verify
