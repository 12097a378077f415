#include "files/output_path.hpp"

#include "files/staged_file.hpp"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <system_error>

namespace twinraster::files {

namespace {

// The nearest part of `directory` that exists ("." for a relative path none of which does).
std::filesystem::path NearestExisting(std::filesystem::path directory) {
  std::error_code ignored;
  while (!directory.empty() && !std::filesystem::exists(directory, ignored)) directory = directory.parent_path();
  return directory.empty() ? std::filesystem::path(".") : directory;
}

bool Writable(const std::filesystem::path& path, const struct stat& status, int access_mode) {
  return !ReadOnlyByMode(status.st_mode) && ::access(path.c_str(), access_mode) == 0;
}

}  // namespace

bool ReadOnlyByMode(mode_t mode) { return (mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0; }

std::string DirectoryTargetProblem(const std::filesystem::path& directory) {
  const std::filesystem::path existing = NearestExisting(directory);
  struct stat status {};
  if (::stat(existing.c_str(), &status) != 0) return existing.string() + ": " + std::strerror(errno);
  const std::string made = existing == directory ? "" : " to make " + directory.string();
  if (!S_ISDIR(status.st_mode)) return existing.string() + " is a file, not a directory";
  // Writing a file into a directory needs both: adding its name (w) and reaching it (x).
  if (!Writable(existing, status, W_OK | X_OK)) return "cannot write in the directory " + existing.string() + made;
  return "";
}

std::string FileTargetProblem(const std::filesystem::path& file) {
  if (file.filename().empty()) return "ends in /: a directory, not a file name";
  struct stat status {};
  if (::stat(file.c_str(), &status) == 0) {
    if (S_ISDIR(status.st_mode)) return "is a directory, not a file name";
    // A device or a pipe would be replaced by a plain file, not written to.
    if (!S_ISREG(status.st_mode)) return "is not a regular file (a device, pipe or socket)";
    // Renaming over a file ignores its own permissions: they are checked here instead.
    if (!Writable(file, status, W_OK)) return "is read-only, so it is not replaced (chmod u+w to allow it)";
  }
  const std::filesystem::path parent = file.parent_path();
  return DirectoryTargetProblem(parent.empty() ? std::filesystem::path(".") : parent);
}

void MakeMissingDirectories(const std::filesystem::path& directory) {
  std::error_code error;
  std::filesystem::create_directories(directory, error);
  if (error) throw FileError(directory.string() + ": cannot create the directory: " + error.message());
}

}  // namespace twinraster::files
