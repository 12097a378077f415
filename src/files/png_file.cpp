#include "files/png_file.hpp"

#include "files/png_bytes.hpp"
#include "files/png_runs.hpp"
#include "files/png_scanlines.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <cstring>
#include <fstream>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string_view>
#include <vector>

namespace twinraster::files {

namespace {

void AppendBigEndian(std::string& out, std::uint32_t value) {
  const char bytes[4] = {static_cast<char>(value >> 24), static_cast<char>(value >> 16), static_cast<char>(value >> 8),
                         static_cast<char>(value)};
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

using png_format::kMaxChunkLength, png_format::kMaxNotes;
constexpr std::size_t kMaxKey = png_format::kMaxKeyword;
constexpr std::size_t kMaxValue = png_format::kMaxNoteValue;

bool HasControlCharacter(std::string_view text) {
  return std::any_of(text.begin(), text.end(), [](char c) {
    const auto b = static_cast<unsigned char>(c);
    return b < 0x20 || b == 0x7f;
  });
}

// All the notes' tEXt chunks, checked before any pixel work is done.
std::string TextChunks(const PngNotes& notes) {
  std::string chunks;
  for (const auto& [key, value] : notes) {
    if (!png_format::IsValidKeyword(key)) {
      throw std::invalid_argument("PNG note key \"" + key + "\" is not 1-" + std::to_string(kMaxKey) +
                                  " printable Latin-1 characters without leading, trailing or double spaces");
    }
    if (value.find('\0') != std::string::npos)
      throw std::invalid_argument("PNG note \"" + key + "\" has a NUL in its value");
    const std::string data = key + '\0' + value;
    AppendChunk(chunks, "tEXt", reinterpret_cast<const std::uint8_t*>(data.data()), data.size());
  }
  return chunks;
}

struct CompressorDeleter {
  void operator()(libdeflate_compressor* c) const { libdeflate_free_compressor(c); }
};

// The zlib stream (RFC 1950) of the image's filtered scanlines, deflated by libdeflate at `level`.
std::vector<std::uint8_t> LibdeflateStream(const Image& image, int level) {
  std::vector<std::uint8_t> raw(png_scanlines::RowBytes(image) * image.height);
  png_scanlines::FilterRows(image, 0, image.height, raw.data());
  const std::unique_ptr<libdeflate_compressor, CompressorDeleter> compressor(libdeflate_alloc_compressor(level));
  if (!compressor) throw std::bad_alloc();
  std::vector<std::uint8_t> zlib(libdeflate_zlib_compress_bound(compressor.get(), raw.size()));
  const std::size_t size = libdeflate_zlib_compress(compressor.get(), raw.data(), raw.size(), zlib.data(), zlib.size());
  if (size == 0) throw FileError("PNG encoding failed");  // cannot happen with a bound-sized buffer
  zlib.resize(size);
  return zlib;
}

// The zlib stream (RFC 1950) of the image's filtered scanlines: at the fastest level the run
// encoder's (png_runs.hpp), which for rendered frames is faster and no larger; else libdeflate's.
std::vector<std::uint8_t> ZlibStream(const Image& image, int level) {
  if (level == kPngFastest) return png_runs::ZlibStream(image);
  return LibdeflateStream(image, level);
}

// The checks every encoding makes before any work.
void CheckEncodable(const Image& image, int level) {
  if (level < 0 || level > kPngSmallest) {
    throw std::invalid_argument("PNG level " + std::to_string(level) + " is outside 0.." +
                                std::to_string(kPngSmallest));
  }
  if (image.width == 0 || image.height == 0 || image.rgba.size() != std::size_t{image.width} * image.height * 4) {
    throw std::invalid_argument("cannot encode an empty or malformed image as PNG");
  }
}

// The file around its image data: signature, header, notes, the data, the end.
std::string PngAround(const Image& image, const std::string& text_chunks, const std::vector<std::uint8_t>& zlib) {
  std::string png(png_format::kSignature);
  png.reserve(8 + 25 + text_chunks.size() + 12 + zlib.size() + 12);
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
  png += text_chunks;
  AppendChunk(png, "IDAT", zlib.data(), zlib.size());
  AppendChunk(png, "IEND", nullptr, 0);
  return png;
}

}  // namespace

std::string EncodePng(const Image& image, int level, const PngNotes& notes) {
  CheckEncodable(image, level);
  const std::string text_chunks = TextChunks(notes);
  return PngAround(image, text_chunks, ZlibStream(image, level));
}

std::string EncodePngWithLibdeflate(const Image& image, int level) {
  CheckEncodable(image, level);
  return PngAround(image, "", LibdeflateStream(image, level));
}

StagedFile StagePng(const std::filesystem::path& file, const Image& image, int level, const PngNotes& notes) {
  return StagedFile(file, EncodePng(image, level, notes));
}

void WritePng(const std::filesystem::path& file, const Image& image, int level, const PngNotes& notes) {
  StagePng(file, image, level, notes).Commit();
}

namespace {

struct ChunkHeader {
  std::uint32_t length = 0;
  std::string type;
};

bool ReadBytes(std::istream& in, char* data, std::size_t size) {
  in.read(data, static_cast<std::streamsize>(size));
  return static_cast<std::size_t>(in.gcount()) == size;
}

// The bytes after the signature, or 0 if `in` is not a PNG; sizing the file first lets every
// chunk length be checked before anything is read or allocated for it.
std::uint64_t BytesAfterSignature(std::istream& in) {
  in.seekg(0, std::ios::end);
  const std::streamoff size = in.tellg();
  in.seekg(0);
  char signature[8];
  if (size < 8 || !ReadBytes(in, signature, 8) || std::string_view(signature, 8) != png_format::kSignature) return 0;
  return static_cast<std::uint64_t>(size) - 8;
}

// The next chunk's header, if its data and CRC lie within the `left` bytes of the file.
std::optional<ChunkHeader> NextChunk(std::istream& in, std::uint64_t& left) {
  char header[8];
  if (left < 8 || !ReadBytes(in, header, 8)) return std::nullopt;
  const ChunkHeader chunk{png_format::BigEndian(header), std::string(header + 4, 4)};
  if (chunk.length > kMaxChunkLength || std::uint64_t{chunk.length} + 4 > left - 8) return std::nullopt;
  left -= 8 + std::uint64_t{chunk.length} + 4;
  return chunk;
}

// The note in a tEXt chunk's data and CRC, if the CRC is right and the note passes the rules.
std::optional<std::pair<std::string, std::string>> ReadNote(std::istream& in, std::uint32_t length) {
  std::string data(std::size_t{length} + 4, '\0');
  if (!ReadBytes(in, data.data(), data.size())) return std::nullopt;
  const std::uint32_t crc = libdeflate_crc32(libdeflate_crc32(0, "tEXt", 4), data.data(), length);
  if (crc != png_format::BigEndian(data.data() + length)) return std::nullopt;
  data.resize(length);
  const std::size_t nul = data.find('\0');
  if (nul == std::string::npos) return std::nullopt;
  std::string key = data.substr(0, nul), value = data.substr(nul + 1);
  if (!png_format::IsValidKeyword(key) || value.size() > kMaxValue || HasControlCharacter(value)) return std::nullopt;
  return std::pair{std::move(key), std::move(value)};
}

}  // namespace

PngNotes ReadPngNotes(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::uint64_t left = BytesAfterSignature(in);
  PngNotes notes;
  while (notes.size() < kMaxNotes) {
    const std::optional<ChunkHeader> chunk = NextChunk(in, left);
    if (!chunk || chunk->type == "IDAT" || chunk->type == "IEND") break;
    // A tEXt chunk too long for a kept note is skipped unread, so a hostile one costs no memory.
    if (chunk->type == "tEXt" && chunk->length <= kMaxKey + 1 + kMaxValue) {
      if (auto note = ReadNote(in, chunk->length)) notes.push_back(std::move(*note));
    } else {
      in.seekg(std::streamoff{chunk->length} + 4, std::ios::cur);
    }
  }
  return notes;
}

}  // namespace twinraster::files
