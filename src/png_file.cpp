#include "png_file.hpp"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STB_IMAGE_WRITE_STATIC
#include <stb/stb_image_write.h>
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace twinraster {

namespace {

void AppendBytes(void* context, void* data, int size) {
  auto* bytes = static_cast<std::vector<unsigned char>*>(context);
  const auto* begin = static_cast<const unsigned char*>(data);
  bytes->insert(bytes->end(), begin, begin + size);
}

std::string SystemError() { return std::strerror(errno); }

}  // namespace

StagedPng::StagedPng(std::filesystem::path target, const Image& image) : target_(std::move(target)) {
  std::vector<unsigned char> png;
  const int stride = static_cast<int>(image.width * 4);
  if (!stbi_write_png_to_func(AppendBytes, &png, static_cast<int>(image.width), static_cast<int>(image.height), 4,
                              image.rgba.data(), stride)) {
    throw FileError(target_.string() + ": PNG encoding failed");
  }
  // Same directory as the target, so that the final rename() is atomic (one file system).
  const std::filesystem::path temporary = target_.string() + ".tmp-" + std::to_string(::getpid());
  std::FILE* out = std::fopen(temporary.c_str(), "wb");
  if (!out) throw FileError(target_.string() + ": cannot write: " + SystemError());
  const bool written = std::fwrite(png.data(), 1, png.size(), out) == png.size() && std::fflush(out) == 0 &&
                       ::fsync(::fileno(out)) == 0;
  const std::string write_error = written ? "" : SystemError();
  if (std::fclose(out) != 0 || !written) {
    const std::string error = written ? SystemError() : write_error;
    std::remove(temporary.c_str());
    throw FileError(target_.string() + ": cannot write: " + error);
  }
  temporary_ = temporary;
}

StagedPng::StagedPng(StagedPng&& other) noexcept
    : target_(std::move(other.target_)), temporary_(std::exchange(other.temporary_, {})) {}

StagedPng::~StagedPng() {
  if (!temporary_.empty()) std::remove(temporary_.c_str());
}

void StagedPng::Commit() {
  if (std::rename(temporary_.c_str(), target_.c_str()) != 0) {
    throw FileError(target_.string() + ": cannot write: " + SystemError());  // the destructor removes the temporary
  }
  temporary_.clear();
}

void WritePng(const std::filesystem::path& file, const Image& image) { StagedPng(file, image).Commit(); }

Image ReadPng(const std::filesystem::path& file) {
  int width = 0, height = 0, channels = 0;
  unsigned char* pixels = stbi_load(file.c_str(), &width, &height, &channels, 4);
  if (!pixels) throw FileError(file.string() + ": cannot read as PNG: " + stbi_failure_reason());
  Image image(static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
  std::memcpy(image.rgba.data(), pixels, image.rgba.size());
  stbi_image_free(pixels);
  return image;
}

}  // namespace twinraster
