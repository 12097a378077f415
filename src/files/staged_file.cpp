#include "files/staged_file.hpp"

#include "files/output_path.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>

namespace twinraster::files {

namespace {
std::string SystemError() { return std::strerror(errno); }
}  // namespace

StagedFile::StagedFile(std::filesystem::path target, std::string_view bytes) : target_(std::move(target)) {
  // Checked here, not at Commit(): every output is staged before the first is committed, so a
  // target that cannot take a file must fail while nothing has been replaced yet.
  // The same rule as the command line's checks before the work (output_path.hpp), for a file that
  // changed since or was never checked: a read-only target is never replaced.
  if (const std::string problem = FileTargetProblem(target_); !problem.empty()) {
    throw FileError(target_.string() + ": " + problem);
  }
  // Same directory as the target, so that the final rename() is atomic (one file system).
  const std::filesystem::path temporary = target_.string() + ".tmp-" + std::to_string(::getpid());
  std::FILE* out = std::fopen(temporary.c_str(), "wb");
  if (!out) throw FileError(target_.string() + ": cannot write: " + SystemError());
  const bool written = std::fwrite(bytes.data(), 1, bytes.size(), out) == bytes.size() && std::fflush(out) == 0 &&
                       ::fsync(::fileno(out)) == 0;
  const std::string write_error = written ? "" : SystemError();
  if (std::fclose(out) != 0 || !written) {
    const std::string error = written ? SystemError() : write_error;
    std::remove(temporary.c_str());
    throw FileError(target_.string() + ": cannot write: " + error);
  }
  temporary_ = temporary;
}

StagedFile::StagedFile(StagedFile&& other) noexcept
    : target_(std::move(other.target_)), temporary_(std::exchange(other.temporary_, {})) {}

StagedFile::~StagedFile() {
  if (!temporary_.empty()) std::remove(temporary_.c_str());
}

void StagedFile::Commit() {
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    throw FileError(target_.string() + ": cannot write: " + SystemError());  // the destructor removes the temporary
  }
  temporary_.clear();
}

}  // namespace twinraster::files
