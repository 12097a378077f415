#include "cli/progress.hpp"

#include "bench/bench_suite.hpp"

#include <unistd.h>

#include <cstdio>
#include <iostream>

namespace twinraster {

namespace {
// Back to the start of the line and clear it: how a terminal status line is replaced or erased.
constexpr const char* kEraseLine = "\r\033[K";
}  // namespace

bool ShowProgressOn(int fd, bool quiet) { return !quiet && ::isatty(fd) == 1; }

Progress::Progress(std::ostream* out) : out_(out) {}

Progress Progress::OnStandardError(bool quiet) {
  return Progress(ShowProgressOn(STDERR_FILENO, quiet) ? &std::cerr : nullptr);
}

Progress::~Progress() { Clear(); }

void Progress::Status(std::string_view text) {
  if (!out_) return;
  // A line longer than the terminal would wrap, and erasing clears only its last row.
  constexpr std::size_t kWidth = 72;
  *out_ << kEraseLine << (text.size() > kWidth ? std::string(text.substr(0, kWidth - 3)) + "..." : std::string(text))
        << std::flush;
  status_showing_ = true;
}

void Progress::Line(std::string_view text) {
  if (!out_) return;
  Clear();
  *out_ << text << "\n" << std::flush;
}

void Progress::Clear() {
  if (!out_ || !status_showing_) return;
  *out_ << kEraseLine << std::flush;
  status_showing_ = false;
}

std::string BenchProgressLine(const BenchRow& row, std::size_t done, std::size_t total) {
  const std::string count = std::to_string(total);
  std::string number = std::to_string(done);
  number.insert(0, count.size() > number.size() ? count.size() - number.size() : 0, ' ');  // rows line up
  std::string line = "[" + number + "/" + count + "] " + row.scene + " " + row.method + ", " +
                     std::to_string(row.threads) + (row.threads == 1 ? " thread" : " threads") + ": ";
  char numbers[160];
  std::snprintf(numbers, sizeof numbers, "frame %.2f ms", row.frame_ms);
  line += numbers;
  if (row.vertex_error_px >= 0) {
    std::snprintf(numbers, sizeof numbers, ", vertex error %.2e px", row.vertex_error_px);
    line += numbers;
  }
  line += ", image error " + std::to_string(row.image_error_px) + " px";
  return line;
}

}  // namespace twinraster
