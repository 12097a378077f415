// Progress on standard error for work that takes a while (a large render's stages, bench rows):
// shown only when standard error is a terminal and --quiet is not given, so that pipes, files,
// standard output and --json never see any of it. Safe to call from several threads: a batch draws
// one scene while it writes another.
#pragma once

#include <cstddef>
#include <functional>
#include <iosfwd>
#include <mutex>
#include <string>
#include <string_view>

namespace twinraster::cli {

// Whether progress belongs on file descriptor `fd`: it is a terminal and quiet is not asked for.
bool ShowProgressOn(int fd, bool quiet);

class Progress {
 public:
  explicit Progress(std::ostream* out);         // nullptr: shows nothing
  static Progress OnStandardError(bool quiet);  // std::cerr when ShowProgressOn(stderr), else nothing
  ~Progress();                                  // erases a status line still showing
  Progress(const Progress&) = delete;
  Progress& operator=(const Progress&) = delete;

  bool active() const { return out_ != nullptr; }
  // One line that the next Status() or Line() replaces, erased at the end: "gpu: drawing...".
  void Status(std::string_view text);
  // A line that stays: one per finished bench row.
  void Line(std::string_view text);
  void Clear();  // erases the status line now
  // Erases the status line and runs `write` (which prints lines that stay), with no status shown
  // meanwhile.
  void Above(const std::function<void()>& write);

 private:
  void ClearLocked();

  std::ostream* out_;
  bool status_showing_ = false;
  std::mutex mutex_;
};

}  // namespace twinraster::cli
