#include "verify/pass1_ring.hpp"

#include <algorithm>
#include <stdexcept>
#include <thread>

namespace twinraster::verify {

bool Pass1Ring::Fits(const DrawList& list) {
  std::size_t vertices = 0;
  for (const DrawMesh& mesh : list.meshes) vertices = std::max(vertices, mesh.positions.size());
  const std::size_t per_vertex = sizeof(BoundedVertex) + sizeof(WindowVertex) + 1;
  return vertices <= kBudget / per_vertex / (kChunk * kSlots);
}

Pass1Ring::Pass1Ring(std::size_t bands, std::size_t draws) : bands_(bands), draws_(draws), slots_(kSlots) {
  for (std::size_t s = 0; s < kSlots; ++s) {
    slots_[s].draws.resize(kChunk);
    slots_[s].writable.store(s);
  }
}

// Yields while waiting: the band waited for may need this core.
template <class Done>
void Pass1Ring::WaitFor(Done&& done) const {
  while (!done()) {
    if (failed_) throw std::runtime_error("another band of the frame failed");
    std::this_thread::yield();
  }
}

const PreparedDraw& Pass1Ring::Get(std::size_t d, const Primitives& primitives) {
  for (std::size_t c = next_.load(); c <= d / kChunk + 1; c = next_.load()) {
    if (next_.compare_exchange_weak(c, c + 1)) Prepare(c, primitives);
  }
  Slot& slot = slots_[d / kChunk % kSlots];
  WaitFor([&] { return slot.ready.load(std::memory_order_acquire) == d / kChunk + 1; });
  return slot.draws[d % kChunk];
}

void Pass1Ring::Finished(std::size_t chunk) {
  Slot& slot = slots_[chunk % kSlots];
  if (slot.finished.fetch_add(1, std::memory_order_acq_rel) + 1 == bands_) {
    slot.finished.store(0, std::memory_order_relaxed);  // before any band can finish the next chunk
    slot.writable.store(chunk + kSlots, std::memory_order_release);
  }
}

void Pass1Ring::Prepare(std::size_t chunk, const Primitives& primitives) {
  if (chunk * kChunk >= draws_) return;
  Slot& slot = slots_[chunk % kSlots];
  WaitFor([&] { return slot.writable.load(std::memory_order_acquire) == chunk; });
  for (std::size_t d = chunk * kChunk; d < std::min(draws_, (chunk + 1) * kChunk); ++d) {
    primitives.PrepareForPass1(d, slot.draws[d % kChunk]);
  }
  slot.ready.store(chunk + 1, std::memory_order_release);
}

}  // namespace twinraster::verify
