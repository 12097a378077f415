// Vectors kept from one frame to the next, process-wide, so that judging a frame reuses memory
// instead of faulting in fresh pages (which for a small scene cost more than judging it). It
// hands out and takes back whole vectors under a lock; it does not know what their elements mean.
#pragma once

#include <cstddef>
#include <mutex>
#include <utility>
#include <vector>

namespace twinraster::verify {

template <typename T>
class BufferPool {
 public:
  // `size` elements, in a vector given back earlier when there is one, holding whatever its earlier
  // user left there (or T's default): for a caller that writes each element before it reads it.
  static std::vector<T> TakeAsLeft(std::size_t size) {
    std::vector<T> buffer = TakeSpare();
    buffer.resize(size);
    return buffer;
  }

  // Keeps `buffer` for a later Take, unless kKept are kept already.
  static void Give(std::vector<T> buffer) {
    const std::lock_guard<std::mutex> hold(Lock());
    if (Spare().size() < kKept) Spare().push_back(std::move(buffer));
  }

 private:
  static constexpr std::size_t kKept = 4;

  static std::vector<T> TakeSpare() {
    std::vector<T> buffer;
    const std::lock_guard<std::mutex> hold(Lock());
    if (!Spare().empty()) {
      buffer = std::move(Spare().back());
      Spare().pop_back();
    }
    return buffer;
  }

  static std::mutex& Lock() {
    static std::mutex lock;
    return lock;
  }
  static std::vector<std::vector<T>>& Spare() {
    static std::vector<std::vector<T>> spare;
    return spare;
  }
};

}  // namespace twinraster::verify
