// PNG files in and out (stb_image / stb_image_write). Writing is atomic: the image goes to a
// temporary file beside the target, which is renamed over it only when complete, so a failed run
// never leaves a truncated PNG or destroys an earlier one.
#pragma once

#include "image.hpp"

#include <filesystem>
#include <stdexcept>

namespace twinraster {

// An output or input file problem; the message names the file.
class FileError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// A PNG written in full to a temporary file beside `target`; Commit() renames it into place. If it
// is destroyed uncommitted it removes the temporary, so a run that fails part-way through writing
// several outputs changes none of them.
class StagedPng {
 public:
  StagedPng(std::filesystem::path target, const Image& image);
  ~StagedPng();
  StagedPng(StagedPng&& other) noexcept;
  StagedPng(const StagedPng&) = delete;
  StagedPng& operator=(const StagedPng&) = delete;
  StagedPng& operator=(StagedPng&&) = delete;
  void Commit();

 private:
  std::filesystem::path target_, temporary_;
};

void WritePng(const std::filesystem::path& file, const Image& image);  // staged and committed at once
Image ReadPng(const std::filesystem::path& file);  // converted to RGBA

}  // namespace twinraster
