#include "verify/frame_shared.hpp"

#include <algorithm>

namespace twinraster::verify {

namespace {

// Bytes of corner colours kept for the bands to share: a lit scene of a few hundred thousand
// triangles. Beyond it each band lights its own draws, as memory matters more than the time.
constexpr std::size_t kCornerBudget = std::size_t{32} << 20;

}  // namespace

FrameShared::FrameShared(const Scene& scene, const DrawList& list)
    : list_(list), neighbours_(std::make_unique<Once<std::vector<std::array<Neighbour, 3>>>[]>(list.meshes.size())) {
  // Vertex colours vary across a triangle as light does: their corners come from the light too.
  const bool smooth = std::any_of(list.meshes.begin(), list.meshes.end(), [](const DrawMesh& m) { return m.smooth(); });
  if (!smooth || list.wireframe) return;
  light_.emplace(scene);
  std::size_t bytes = 0;
  for (const DrawCall& draw : list.draws)
    bytes += list.meshes[draw.mesh].triangles.size() * sizeof(Corners::value_type);
  if (bytes <= kCornerBudget) corners_ = std::make_unique<Once<Corners>[]>(list.draws.size());
}

const FrameShared::Corners& FrameShared::CornerColours(std::size_t d, Corners& scratch) const {
  if (!corners_) return scratch = light_->CornerColours(d);
  Once<Corners>& kept = corners_[d];
  std::call_once(kept.flag, [&] { kept.value = light_->CornerColours(d); });
  return kept.value;
}

const std::vector<std::array<Neighbour, 3>>& FrameShared::Neighbours(std::size_t mesh) const {
  auto& kept = neighbours_[mesh];
  std::call_once(kept.flag, [&] { kept.value = MeshNeighbours(list_.meshes[mesh]); });
  return kept.value;
}

}  // namespace twinraster::verify
