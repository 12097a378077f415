// Draws DrawLists with GpuRenderer in a child process, so that a Vulkan driver that crashes or
// hangs becomes a result the caller reports, not the end of the caller (as Mesa's deqp-runner
// isolates its test groups).
#pragma once

#include "base/stopwatch.hpp"
#include "chain/draw_list.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image.hpp"

#include <functional>
#include <memory>
#include <optional>
#include <string>

namespace twinraster::gpu {

enum class GpuOutcome {
  kRendered,     // `image` holds the frame
  kUnavailable,  // no usable Vulkan device (GpuUnavailable in the child); `problem` says why
  kBadList,      // the renderer refused the list (std::invalid_argument); `problem` says why
  kCrashed,      // the child died (`signal`, e.g. "SIGABRT"), or failed in a way it cannot go on from
  kTimedOut,     // the child passed the time limit and was killed
};

struct IsolatedGpuResult {
  GpuOutcome outcome = GpuOutcome::kCrashed;
  Image image;
  // Known once the child has its device, so also when a draw then crashes; empty name when the
  // child died before that.
  DeviceIdentity device;
  GpuTimings timings;
  double device_ms = 0;  // instance, device and pipelines: the child's first list only
  std::string signal;    // kCrashed by a signal: "SIGABRT", "SIGSEGV", ...
  std::string problem;   // what went wrong, in words, for every outcome but kRendered
  // Wall time this process spent on the list minus what the child measured drawing it: fork or
  // sending the list, the pipe, the pixels coming back. What isolation costs.
  double isolation_ms = 0;
};

struct IsolationOptions {
  GpuOptions gpu;
  double timeout_seconds = 0;  // per list; 0: wait as long as the child takes
  // Called in this process just before each fork, to quiet its other threads: a child inherits
  // every lock they hold at that moment, held (under ASan a batch's writer thread, caught
  // allocating, left the child hung in its first calloc).
  std::function<void()> before_fork;
};

// One child process with one GpuRenderer, kept for every list while it lives. The first list (and
// the first after a crash) is inherited by a fresh child copy-on-write, so a single render sends
// nothing; later lists go to the living child through a pipe, so its device and pipelines are
// made once. This process never loads the Vulkan driver.
//
// For tests only: TWINRASTER_TEST_GPU_FAULT=abort or =hang makes the child abort, or sleep
// forever, once it has its device and before it draws.
class GpuProcess {
 public:
  explicit GpuProcess(IsolationOptions options);
  ~GpuProcess();  // kills the child
  GpuProcess(const GpuProcess&) = delete;
  GpuProcess& operator=(const GpuProcess&) = delete;

  // Throws only std::system_error when the operating system refuses a pipe or a process.
  IsolatedGpuResult Render(const DrawList& list);
  // Render in two halves, so that this process can work while the child draws: Submit hands the
  // list over and returns, Collect waits for the answer. One list at a time; Submit throws as
  // Render does, Collect never.
  void Submit(const DrawList& list);
  IsolatedGpuResult Collect();
  // The living child's device, from its first answer on; empty before that and after a crash.
  const DeviceIdentity& device() const { return device_; }

 private:
  struct Child;
  void Hand(const DrawList& list);   // to the living child, or to a fresh one
  void Spawn(const DrawList& list);  // a fresh child, born with the list
  // Reaps a child that ended its answer early, and says how it ended in `result`.
  void ReapLost(bool timed_out, IsolatedGpuResult& result);

  IsolationOptions options_;
  std::unique_ptr<Child> child_;  // none before the first list and after a crash
  DeviceIdentity device_;         // the living child's
  struct Pending {                // the list submitted and not yet collected
    Stopwatch clock;              // from its hand-over
    double submit_ms = 0;         // the hand-over's own time
    std::uint32_t width = 0, height = 0;
  };
  std::optional<Pending> pending_;
};

// One list in a child of its own.
IsolatedGpuResult RenderIsolated(const DrawList& list, const IsolationOptions& options);

}  // namespace twinraster::gpu
