#include "cli/progress.hpp"

#include <unistd.h>

#include <iostream>

namespace twinraster::cli {

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
  const std::lock_guard lock(mutex_);
  // A line longer than the terminal would wrap, and erasing clears only its last row.
  constexpr std::size_t kWidth = 72;
  *out_ << kEraseLine << (text.size() > kWidth ? std::string(text.substr(0, kWidth - 3)) + "..." : std::string(text))
        << std::flush;
  status_showing_ = true;
}

void Progress::Line(std::string_view text) {
  if (!out_) return;
  const std::lock_guard lock(mutex_);
  ClearLocked();
  *out_ << text << "\n" << std::flush;
}

void Progress::Clear() {
  const std::lock_guard lock(mutex_);
  ClearLocked();
}

void Progress::Above(const std::function<void()>& write) {
  const std::lock_guard lock(mutex_);
  ClearLocked();
  write();
}

void Progress::ClearLocked() {
  if (!out_ || !status_showing_) return;
  *out_ << kEraseLine << std::flush;
  status_showing_ = false;
}

}  // namespace twinraster::cli
