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

void WritePng(const std::filesystem::path& file, const Image& image);
Image ReadPng(const std::filesystem::path& file);  // converted to RGBA

}  // namespace twinraster
