// An output file written in full to a temporary file beside its target and renamed into place by
// Commit(): a run that fails part-way never leaves a truncated file or destroys an earlier one, and
// a read-only file is never replaced (output_path.hpp). It makes no directory.
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string_view>

namespace twinraster::files {

// An output or input file problem; the message names the file.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

class StagedFile {
 public:
  StagedFile(std::filesystem::path target, std::string_view bytes);  // throws FileError
  ~StagedFile();                                                     // removes the temporary unless committed
  StagedFile(StagedFile&& other) noexcept;
  StagedFile(const StagedFile&) = delete;
  StagedFile& operator=(const StagedFile&) = delete;
  StagedFile& operator=(StagedFile&&) = delete;
  void Commit();  // throws FileError

 private:
  std::filesystem::path target_, temporary_;
};

}  // namespace twinraster::files
