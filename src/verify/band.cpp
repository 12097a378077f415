#include "verify/band.hpp"

#include <algorithm>
#include <thread>

namespace twinraster::verify {

int BandRows(int rows) {
  const int threads = int(std::clamp(std::thread::hardware_concurrency(), 1u, unsigned((rows + 15) / 16)));
  return ((rows + threads - 1) / threads + 15) / 16 * 16;
}

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

void MergeBands(const std::vector<std::unique_ptr<Band>>& bands, Verification& result) {
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

}  // namespace twinraster::verify
