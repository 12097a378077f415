// Milliseconds elapsed on a steady clock, for the stage timings the commands report.
#pragma once

#include <chrono>

namespace twinraster {

class Stopwatch {
 public:
  double Milliseconds() const {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start_).count();
  }
  // Milliseconds since construction or the previous lap, then start again: one stage's time.
  double Lap() {
    const double ms = Milliseconds();
    start_ = std::chrono::steady_clock::now();
    return ms;
  }

 private:
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace twinraster
