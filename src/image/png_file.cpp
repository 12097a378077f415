#include "image/png_file.hpp"

#include <cstring>

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
  static_cast<std::string*>(context)->append(static_cast<const char*>(data), static_cast<std::size_t>(size));
}
}  // namespace

std::string EncodePng(const Image& image) {
  std::string png;
  if (!stbi_write_png_to_func(AppendBytes, &png, static_cast<int>(image.width), static_cast<int>(image.height), 4,
                              image.rgba.data(), static_cast<int>(image.width * 4))) {
    throw FileError("PNG encoding failed");
  }
  return png;
}

StagedFile StagePng(const std::filesystem::path& file, const Image& image) { return StagedFile(file, EncodePng(image)); }

void WritePng(const std::filesystem::path& file, const Image& image) { StagePng(file, image).Commit(); }

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
