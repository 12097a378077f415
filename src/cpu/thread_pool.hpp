// Worker threads that live as long as the process: every parallel stage of the twin hands them
// parts of its work, instead of starting threads per frame (for small scenes, starting threads
// cost more than the work they shared).
#pragma once

#include <functional>

namespace twinraster::cpu {

// The threads the hardware runs at once (0 if unknown); 1 in a build without threads.
unsigned HardwareThreads();

// Runs fn(part) once for every part in [0, parts) and returns when all have finished. The calling
// thread takes parts too; the pool grows to parts - 1 workers if it has fewer. Each part must
// write only its own outputs, so that results never depend on which thread ran which part. Calls
// from different threads take turns; a call from inside fn runs its parts inline, one by one.
void RunParts(unsigned parts, const std::function<void(unsigned)>& fn);

// While one lives (a render's stages follow each other closely), idle workers spin a little for
// the next parts before they sleep; with none, they sleep at once, so that a finished render
// leaves the other cores to what follows it (the PNG, another process).
class KeepPoolSpinning {
 public:
  KeepPoolSpinning();
  ~KeepPoolSpinning();
  KeepPoolSpinning(const KeepPoolSpinning&) = delete;
  KeepPoolSpinning& operator=(const KeepPoolSpinning&) = delete;
};

}  // namespace twinraster::cpu
