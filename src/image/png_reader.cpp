// ReadPng and DecodePng: PNG files from anywhere (any GPU, any engine, a bug report), read with
// libspng, which checks every chunk's CRC and the zlib stream's Adler-32 and has limits. Nothing is
// decoded before the declared size passes kMaxPngSide and the caller's check; the only large
// allocation is the RGBA image itself; a file is streamed, never read whole.
#include "image/png_file.hpp"

#include <spng.h>

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <new>
#include <sstream>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster {
namespace {

// Ancillary chunks libspng keeps while reading (text, ICC profiles, ...): one at most 1 MiB, all
// together at most 8 MiB; IDAT is streamed and not counted.
constexpr std::size_t kChunkLimit = std::size_t{1} << 20;
constexpr std::size_t kChunkCacheLimit = std::size_t{8} << 20;

struct ContextFree {
  void operator()(spng_ctx* ctx) const { spng_ctx_free(ctx); }
};
using Context = std::unique_ptr<spng_ctx, ContextFree>;

// Binds a new decoder to the bytes (a file, rewound, or a buffer), strict about every checksum.
using Source = std::function<int(spng_ctx*)>;

[[noreturn]] void Refuse(const std::string& name, const std::string& problem) {
  throw FileError(name + ": cannot read as PNG: " + problem);
}

// libspng's own words for its error codes are static English; none comes from the file.
std::string Problem(int error) {
  switch (error) {
    case SPNG_IO_EOF:
    case SPNG_IO_ERROR:
    case SPNG_EIO:
      return "the file ends before the PNG does (truncated)";
    case SPNG_ESIGNATURE:
      return "not a PNG file (its first 8 bytes are not the PNG signature)";
    case SPNG_EUSER_WIDTH:
    case SPNG_EUSER_HEIGHT:
      return "it declares a side over " + std::to_string(kMaxPngSide) + " pixels, the most twinraster reads";
    case SPNG_EMEM:
      return "out of memory";
    case SPNG_ECHUNK_LIMITS:
      return "an ancillary chunk holds more than twinraster keeps (1 MiB for one, 8 MiB in all, once inflated)";
    default: {
      const char* text = spng_strerror(error);
      return std::string("corrupt: ") + (text != nullptr && *text != '\0' ? text : "libspng error " + std::to_string(error));
    }
  }
}

#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
// Under libFuzzer (the fuzz preset) checksums are not checked, so that mutated inputs reach the
// decoder and the verifier rather than stopping at a CRC, as PNG fuzzers usually do.
constexpr int kChecksums = SPNG_CRC_USE, kContextFlags = SPNG_CTX_IGNORE_ADLER32;
#else
constexpr int kChecksums = SPNG_CRC_ERROR, kContextFlags = 0;
#endif

Context NewDecoder(const Source& source, const std::string& name) {
  Context ctx(spng_ctx_new(kContextFlags));
  if (!ctx) Refuse(name, "out of memory");
  spng_set_crc_action(ctx.get(), kChecksums, kChecksums);
  spng_set_chunk_limits(ctx.get(), kChunkLimit, kChunkCacheLimit);
  spng_set_image_limits(ctx.get(), kMaxPngSide, kMaxPngSide);
  if (const int e = source(ctx.get())) Refuse(name, Problem(e));
  return ctx;
}

std::string Hex(const char* bytes, std::size_t size) {
  static const char kDigits[] = "0123456789abcdef";
  std::string text;
  for (std::size_t i = 0; i < size; ++i) {
    const auto b = static_cast<unsigned char>(bytes[i]);
    text += (i ? " " : "") + std::string{kDigits[b >> 4], kDigits[b & 15]};
  }
  return text;
}

// Every chunk's type must be four ASCII letters (PNG spec 5.4). libspng skips an unknown ancillary
// chunk without looking at its type, so the chunk headers are walked once first; the bytes of a
// bad type are shown in hex, never copied to the terminal. Whatever else is wrong (a cut-off
// file, a length past the end) is left to libspng to name.
void CheckChunkTypes(std::istream& in, const std::string& name) {
  static constexpr char kSignature[8] = {'\x89', 'P', 'N', 'G', '\r', '\n', '\x1a', '\n'};
  char header[8];
  if (!in.read(header, 8) || !std::equal(header, header + 8, kSignature)) return;  // libspng names it
  while (in.read(header, 8)) {
    const bool letters = std::all_of(header + 4, header + 8, [](char c) {
      return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z');
    });
    if (!letters) Refuse(name, "corrupt: a chunk type that is not four ASCII letters (bytes " + Hex(header + 4, 4) + ")");
    if (std::string_view(header + 4, 4) == "IEND") return;
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i) length = length << 8 | static_cast<unsigned char>(header[i]);
    if (!in.seekg(std::streamoff{length} + 4, std::ios::cur)) return;
  }
}

// Adam7's passes: where each starts and how far apart its pixels are, across.
constexpr std::uint32_t kPassX0[7] = {0, 4, 0, 2, 0, 1, 0};
constexpr std::uint32_t kPassDx[7] = {8, 8, 4, 4, 2, 2, 1};

std::uint32_t ScanlineWidth(const spng_ihdr& ihdr, int pass) {
  if (ihdr.interlace_method == 0) return ihdr.width;
  const std::uint32_t x0 = kPassX0[pass], dx = kPassDx[pass];
  return ihdr.width > x0 ? (ihdr.width - x0 + dx - 1) / dx : 0;
}

// libspng maps a palette index past the PLTE's last entry to opaque black; such a file is
// corrupt (PNG spec 11.2.3), so every index is read once more, scanline by scanline, and checked.
void CheckPaletteIndices(const Source& source, const std::string& name, const spng_ihdr& ihdr) {
  const Context ctx = NewDecoder(source, name);
  spng_plte plte{};
  if (const int e = spng_get_plte(ctx.get(), &plte)) Refuse(name, Problem(e));
  std::size_t row_bytes = 0;
  if (const int e = spng_decoded_image_size(ctx.get(), SPNG_FMT_PNG, &row_bytes)) Refuse(name, Problem(e));
  row_bytes /= ihdr.height;
  if (const int e = spng_decode_image(ctx.get(), nullptr, 0, SPNG_FMT_PNG, SPNG_DECODE_PROGRESSIVE)) Refuse(name, Problem(e));
  std::vector<std::uint8_t> scanline(row_bytes);
  const unsigned bits = ihdr.bit_depth, per_byte = 8 / bits, mask = (1u << bits) - 1;
  for (;;) {
    spng_row_info row{};
    if (const int e = spng_get_row_info(ctx.get(), &row)) {
      if (e == SPNG_EOI) break;
      Refuse(name, Problem(e));
    }
    const int e = spng_decode_scanline(ctx.get(), scanline.data(), scanline.size());
    if (e != 0 && e != SPNG_EOI) Refuse(name, Problem(e));
    const std::uint32_t width = ScanlineWidth(ihdr, row.pass);
    for (std::uint32_t x = 0; x < width; ++x) {
      const unsigned shift = 8 - bits * (x % per_byte + 1);
      const unsigned index = (scanline[x / per_byte] >> shift) & mask;
      if (index >= plte.n_entries) {
        Refuse(name, "corrupt: palette index " + std::to_string(index) + " in row " + std::to_string(row.row_num) +
                         ", but the palette has " + std::to_string(plte.n_entries) + " entries");
      }
    }
    if (e == SPNG_EOI) break;
  }
}

Image Decode(std::istream& chunks, const Source& source, const std::string& name, const PngSizeCheck& check) {
  CheckChunkTypes(chunks, name);
  const Context ctx = NewDecoder(source, name);
  spng_ihdr ihdr{};
  if (const int e = spng_get_ihdr(ctx.get(), &ihdr)) Refuse(name, Problem(e));
  if (check) check(ihdr.width, ihdr.height);
  Image image;
  try {
    image = Image(ihdr.width, ihdr.height);
  } catch (const std::bad_alloc&) {
    Refuse(name, "its " + std::to_string(ihdr.width) + " x " + std::to_string(ihdr.height) + " pixels need " +
                     std::to_string(std::size_t{ihdr.width} * ihdr.height * 4 >> 20) + " MiB, more than this machine gave");
  }
  if (const int e = spng_decode_image(ctx.get(), image.rgba.data(), image.rgba.size(), SPNG_FMT_RGBA8, SPNG_DECODE_TRNS)) {
    Refuse(name, Problem(e));
  }
  // The chunks after the pixels, to IEND: a cut-off or corrupt end is a corrupt file too.
  if (const int e = spng_decode_chunks(ctx.get())) Refuse(name, Problem(e));
  if (ihdr.color_type == SPNG_COLOR_TYPE_INDEXED) CheckPaletteIndices(source, name, ihdr);
  return image;
}

struct FileClose {
  void operator()(std::FILE* f) const { std::fclose(f); }
};

}  // namespace

Image ReadPng(const std::filesystem::path& file, const PngSizeCheck& check) {
  const std::unique_ptr<std::FILE, FileClose> in(std::fopen(file.c_str(), "rb"));
  std::ifstream chunks(file, std::ios::binary);
  std::error_code error;
  if (!in || !chunks || std::filesystem::is_directory(file, error)) throw FileError(file.string() + ": cannot open for reading");
  return Decode(
      chunks,
      [&](spng_ctx* ctx) {
        std::rewind(in.get());
        return spng_set_png_file(ctx, in.get());
      },
      file.string(), check);
}

Image DecodePng(std::string_view bytes, const std::string& name, const PngSizeCheck& check) {
  std::istringstream chunks{std::string(bytes)};
  return Decode(chunks, [&](spng_ctx* ctx) { return spng_set_png_buffer(ctx, bytes.data(), bytes.size()); }, name, check);
}

}  // namespace twinraster
