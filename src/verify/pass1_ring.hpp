// The draws prepared for pass 1, shared by the bands of a frame: each draw is prepared once for
// the frame, a chunk of draws at a time, by whichever band first reaches the chunk before it, into
// a ring of chunks that every band then reads in draw order. It does not occlude or judge pixels
// (verifier.cpp's bands do), nor assemble primitives (primitives.hpp does).
#pragma once

#include "chain/draw_list.hpp"
#include "verify/primitives.hpp"

#include <atomic>
#include <cstddef>
#include <vector>

namespace twinraster::verify {

// Whole chunks, so that no two cores write the same cache lines. A band ahead of the others
// prepares for them; one behind finds its draws ready. A chunk's slot is reused only once every
// band has finished with the chunk it held.
class Pass1Ring {
 public:
  static constexpr std::size_t kChunk = 256, kSlots = 16;        // draws
  static constexpr std::size_t kBudget = std::size_t{64} << 20;  // bytes of geometry the ring may hold

  // Whether the ring of `list`'s draws fits the budget; if not, each band prepares its own draws.
  static bool Fits(const DrawList& list);

  Pass1Ring(std::size_t bands, std::size_t draws);

  // Draw d, prepared. The band asking prepares (with `primitives`) the chunks up to the one after
  // d's that no band has claimed yet, so that the next chunk is usually ready when it is reached.
  const PreparedDraw& Get(std::size_t d, const Primitives& primitives);

  // One band is done with `chunk` (called after its last draw, or the frame's).
  void Finished(std::size_t chunk);

  void Fail() { failed_ = true; }  // a band threw: the others stop rather than wait for it

 private:
  struct Slot {
    std::vector<PreparedDraw> draws;
    std::atomic<std::size_t> ready{0};     // the chunk held + 1 once prepared
    std::atomic<std::size_t> writable{0};  // the chunk that may be written here
    std::atomic<std::size_t> finished{0};  // bands done with the chunk held
  };

  void Prepare(std::size_t chunk, const Primitives& primitives);
  template <class Done>
  void WaitFor(Done&& done) const;

  std::size_t bands_, draws_;
  std::vector<Slot> slots_;
  std::atomic<std::size_t> next_{0};  // the first chunk no band has claimed
  std::atomic<bool> failed_{false};
};

}  // namespace twinraster::verify
