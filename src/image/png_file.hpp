// PNG files in and out (stb_image / stb_image_write); outputs are staged (staged_file.hpp), so a
// failed run never leaves a truncated PNG or destroys an earlier one.
#pragma once

#include "image/image.hpp"
#include "image/staged_file.hpp"

#include <filesystem>
#include <string>

namespace twinraster {

std::string EncodePng(const Image& image);  // the bytes of a PNG file
StagedFile StagePng(const std::filesystem::path& file, const Image& image);
void WritePng(const std::filesystem::path& file, const Image& image);  // staged and committed at once
Image ReadPng(const std::filesystem::path& file);                      // converted to RGBA; throws FileError

}  // namespace twinraster
