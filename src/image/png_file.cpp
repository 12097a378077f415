#include "image/png_file.hpp"

#include <libdeflate.h>

#include <cstring>
#include <memory>
#include <stdexcept>
#include <vector>

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_STATIC
#define STBI_ONLY_PNG
#include <stb/stb_image.h>

namespace twinraster {

namespace {

void AppendBigEndian(std::string& out, std::uint32_t value) {
  const char bytes[4] = {static_cast<char>(value >> 24), static_cast<char>(value >> 16),
                         static_cast<char>(value >> 8), static_cast<char>(value)};
  out.append(bytes, 4);
}

// A chunk is its length, its type, its data, and a CRC-32 of type and data (PNG spec, 5.3).
void AppendChunk(std::string& out, const char (&type)[5], const std::uint8_t* data, std::size_t size) {
  AppendBigEndian(out, static_cast<std::uint32_t>(size));
  const std::size_t type_at = out.size();
  out.append(type, 4);
  out.append(reinterpret_cast<const char*>(data), size);
  const std::uint32_t crc = libdeflate_crc32(0, out.data() + type_at, 4 + size);
  AppendBigEndian(out, crc);
}

// Every scanline gets the "Up" filter (each byte minus the byte above it). Rendered images are
// mostly flat runs and straight edges, where Up leaves long runs of zeros for deflate; trying
// all five filters per row, as stb_image_write does, costs more than it saves at fast levels.
std::vector<std::uint8_t> FilteredScanlines(const Image& image) {
  const std::size_t stride = std::size_t{image.width} * 4;
  std::vector<std::uint8_t> raw((stride + 1) * image.height);
  for (std::uint32_t y = 0; y < image.height; ++y) {
    std::uint8_t* out = &raw[(stride + 1) * y];
    const std::uint8_t* row = image.rgba.data() + stride * y;
    if (y == 0) {
      out[0] = 0;  // None: the first row has nothing above it
      std::memcpy(out + 1, row, stride);
      continue;
    }
    out[0] = 2;  // Up
    const std::uint8_t* above = row - stride;
    for (std::size_t i = 0; i < stride; ++i) out[1 + i] = static_cast<std::uint8_t>(row[i] - above[i]);
  }
  return raw;
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

}  // namespace

std::string EncodePng(const Image& image, int level) {
  if (level < 0 || level > kPngSmallest) {
    throw std::invalid_argument("PNG level " + std::to_string(level) + " is outside 0.." + std::to_string(kPngSmallest));
  }
  if (image.width == 0 || image.height == 0 || image.rgba.size() != std::size_t{image.width} * image.height * 4) {
    throw std::invalid_argument("cannot encode an empty or malformed image as PNG");
  }
  const std::vector<std::uint8_t> raw = FilteredScanlines(image);
  const std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(libdeflate_alloc_compressor(level));
  if (!compressor) throw std::bad_alloc();
  std::vector<std::uint8_t> zlib(libdeflate_zlib_compress_bound(compressor.get(), raw.size()));
  const std::size_t zlib_size = libdeflate_zlib_compress(compressor.get(), raw.data(), raw.size(), zlib.data(), zlib.size());
  if (zlib_size == 0) throw FileError("PNG encoding failed");  // cannot happen with a bound-sized buffer

  std::string png("\x89PNG\r\n\x1a\n", 8);
  png.reserve(8 + 25 + 12 + zlib_size + 12);
  std::uint8_t header[13] = {};
  for (int i = 0; i < 4; ++i) {
    header[i] = static_cast<std::uint8_t>(image.width >> (24 - 8 * i));
    header[4 + i] = static_cast<std::uint8_t>(image.height >> (24 - 8 * i));
  }
  header[8] = 8;   // bits per channel
  header[9] = 6;   // colour type: RGBA
  header[10] = 0;  // compression: deflate
  header[11] = 0;  // filtering: adaptive (per-row filter bytes)
  header[12] = 0;  // no interlace
  AppendChunk(png, "IHDR", header, sizeof header);
  AppendChunk(png, "IDAT", zlib.data(), zlib_size);
  AppendChunk(png, "IEND", nullptr, 0);
  return png;
}

StagedFile StagePng(const std::filesystem::path& file, const Image& image, int level) {
  return StagedFile(file, EncodePng(image, level));
}

void WritePng(const std::filesystem::path& file, const Image& image, int level) { StagePng(file, image, level).Commit(); }

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
