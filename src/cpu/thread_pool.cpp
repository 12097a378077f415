#include "cpu/thread_pool.hpp"

#include "cpu/platform.hpp"

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

namespace twinraster::cpu {

namespace {

// Set while a thread runs parts (and always in pool workers), so that nested calls run inline
// instead of waiting for themselves.
thread_local bool t_inside_parts = false;

// How long a thread spins before it sleeps: a wake-up through the kernel costs tens of
// microseconds, more than one stage of a chunk often takes.
constexpr int kSpins = 20000;

// Renders under way (KeepPoolSpinning): idle workers spin only while one is, since the next part
// is then near; once the last ends, they sleep at once and leave the core to other work.
std::atomic<int> g_spinning_holds{0};

// One RunParts call. Workers hold it by shared_ptr: one that wakes late finds every part taken
// and lets go, never touching a later job's counters.
struct Job {
  const std::function<void(unsigned)>* fn = nullptr;
  unsigned parts = 0;
  std::atomic<unsigned> next_part{0};
  // Parts not yet finished: decremented under ThreadPool::mutex_ (so the caller's wait cannot miss
  // the last one), read without it while the caller spins.
  std::atomic<unsigned> unfinished{0};
  std::exception_ptr error;  // likewise: the first part's exception, rethrown by the caller
};

class ThreadPool {
 public:
  ~ThreadPool() {
    {
      const std::lock_guard lock(mutex_);
      stopping_ = true;
    }
    wake_.notify_all();
    for (std::thread& worker : workers_) worker.join();
  }

  void Run(unsigned parts, const std::function<void(unsigned)>& fn) {
    const std::lock_guard turn(turn_);  // one job at a time
    const auto job = std::make_shared<Job>();
    job->fn = &fn;
    job->parts = parts;
    job->unfinished.store(parts);
    {
      const std::lock_guard lock(mutex_);
      while (workers_.size() + 1 < parts) workers_.emplace_back([this] { Work(); });
      current_ = job;
      generation_.fetch_add(1, std::memory_order_release);
    }
    wake_.notify_all();
    TakeParts(*job);
    for (int spin = 0; spin < kSpins && job->unfinished.load(std::memory_order_acquire) != 0; ++spin) CpuRelax();
    std::unique_lock lock(mutex_);
    done_.wait(lock, [&] { return job->unfinished.load() == 0; });
    current_ = nullptr;
    if (job->error) std::rethrow_exception(job->error);
  }

 private:
  void Work() {
    t_inside_parts = true;
    std::uint64_t seen = 0;
    for (;;) {
      std::shared_ptr<Job> job;
      for (int spin = 0; spin < kSpins && generation_.load(std::memory_order_acquire) == seen &&
                         g_spinning_holds.load(std::memory_order_relaxed) > 0;
           ++spin) {
        CpuRelax();
      }
      {
        std::unique_lock lock(mutex_);
        wake_.wait(lock, [&] { return stopping_ || generation_.load() != seen; });
        if (stopping_) return;
        seen = generation_.load();
        job = current_;
      }
      if (job) TakeParts(*job);
    }
  }

  // Takes parts until none is left; the last part to finish wakes the caller.
  void TakeParts(Job& job) {
    const bool was_inside = t_inside_parts;
    t_inside_parts = true;
    for (;;) {
      const unsigned part = job.next_part.fetch_add(1);
      if (part >= job.parts) break;
      std::exception_ptr error;
      try {
        (*job.fn)(part);
      } catch (...) {
        error = std::current_exception();
      }
      const std::lock_guard lock(mutex_);
      if (error && !job.error) job.error = error;
      if (job.unfinished.fetch_sub(1, std::memory_order_acq_rel) == 1) done_.notify_all();
    }
    t_inside_parts = was_inside;
  }

  std::mutex turn_;   // serialises callers
  std::mutex mutex_;  // guards everything below and the jobs' counters
  std::condition_variable wake_, done_;
  std::vector<std::thread> workers_;
  bool stopping_ = false;
  std::atomic<std::uint64_t> generation_{0};
  std::shared_ptr<Job> current_;
};

}  // namespace

KeepPoolSpinning::KeepPoolSpinning() { g_spinning_holds.fetch_add(1, std::memory_order_relaxed); }
KeepPoolSpinning::~KeepPoolSpinning() { g_spinning_holds.fetch_sub(1, std::memory_order_relaxed); }

unsigned HardwareThreads() { return std::thread::hardware_concurrency(); }

void RunParts(unsigned parts, const std::function<void(unsigned)>& fn) {
  if (parts == 0) return;
  if (parts == 1 || t_inside_parts) {
    for (unsigned part = 0; part < parts; ++part) fn(part);
    return;
  }
  static ThreadPool pool;  // joined at exit
  pool.Run(parts, fn);
}

}  // namespace twinraster::cpu
