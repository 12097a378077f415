// PNG files in and out: written by a small encoder over libdeflate (fast enough for a 1920x1080
// frame in a few tens of milliseconds), read by stb_image. Outputs are staged (staged_file.hpp),
// so a failed run never leaves a truncated PNG or destroys an earlier one.
#pragma once

#include "image/image.hpp"
#include "image/staged_file.hpp"

#include <filesystem>
#include <string>

namespace twinraster {

// libdeflate's compression levels: 0 stores the pixels uncompressed, 1 (the default) is the
// fastest compression, 12 the smallest file. Every level is lossless.
inline constexpr int kPngFastest = 1;
inline constexpr int kPngSmallest = 12;

std::string EncodePng(const Image& image, int level = kPngFastest);  // the bytes of a PNG file
StagedFile StagePng(const std::filesystem::path& file, const Image& image, int level = kPngFastest);
void WritePng(const std::filesystem::path& file, const Image& image, int level = kPngFastest);  // staged and committed at once
Image ReadPng(const std::filesystem::path& file);  // converted to RGBA; throws FileError

}  // namespace twinraster
