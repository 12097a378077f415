// ReadPng and DecodePng: PNG files from anywhere (any GPU, any engine, a bug report), read with
// libspng, which checks every chunk's CRC and the zlib stream's Adler-32 and has limits, unless
// the file is of the narrow form renderers write, which png_fast_reader.hpp reads faster. Nothing is
// decoded before the declared size passes kMaxPngSide and the caller's check; the only large
// allocation is the RGBA image itself (and, read by the fast reader, the image data, at most 8 MiB
// of it); a file is otherwise streamed, never read whole.
#include "image/png_bytes.hpp"
#include "image/png_fast_reader.hpp"
#include "image/png_file.hpp"

#include <spng.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <functional>
#include <memory>
#include <new>
#include <optional>
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
    case SPNG_EIO: return "the file ends before the PNG does (truncated)";
    case SPNG_IO_ERROR: return "a read error";
    case SPNG_ESIGNATURE: return "not a PNG file (its first 8 bytes are not the PNG signature)";
    case SPNG_EUSER_WIDTH:
    case SPNG_EUSER_HEIGHT:
      return "it declares a side over " + std::to_string(kMaxPngSide) + " pixels, the most twinraster reads";
    case SPNG_EMEM: return "out of memory";
    case SPNG_ECHUNK_LIMITS:
      return "an ancillary chunk holds more than twinraster keeps (1 MiB for one, 8 MiB in all, once inflated)";
    default: {
      const char* text = spng_strerror(error);
      return std::string("corrupt: ") +
             (text != nullptr && *text != '\0' ? text : "libspng error " + std::to_string(error));
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

// Adam7's passes: where each starts and how far apart its pixels are, across and down.
constexpr std::uint32_t kPassX0[7] = {0, 4, 0, 2, 0, 1, 0};
constexpr std::uint32_t kPassDx[7] = {8, 8, 4, 4, 2, 2, 1};
constexpr std::uint32_t kPassY0[7] = {0, 0, 4, 0, 2, 0, 1};
constexpr std::uint32_t kPassDy[7] = {8, 8, 8, 4, 4, 2, 2};

std::uint32_t PassSize(std::uint32_t size, std::uint32_t start, std::uint32_t step) {
  return size > start ? (size - start + step - 1) / step : 0;
}

// What IHDR declares, as far as the walk below needs it.
struct Header {
  std::uint32_t width = 0, height = 0;
  unsigned depth = 0, colour = 0, interlace = 0;
};

// The bytes the image data must inflate to: each row's filter byte and samples, for the whole
// image or for each of Adam7's passes (PNG spec 7.2, 8.2). 0 for a header libspng will refuse.
std::uint64_t FilteredSize(const Header& h) {
  const unsigned channels = h.colour == 0   ? 1
                            : h.colour == 2 ? 3
                            : h.colour == 3 ? 1
                            : h.colour == 4 ? 2
                            : h.colour == 6 ? 4
                                            : 0;
  const std::uint64_t bits = std::uint64_t{channels} * h.depth;
  const auto rows = [&](std::uint64_t width, std::uint64_t height) {
    return width == 0 ? 0 : height * (1 + (width * bits + 7) / 8);
  };
  if (h.interlace == 0) return rows(h.width, h.height);
  std::uint64_t size = 0;
  for (int p = 0; p < 7; ++p)
    size += rows(PassSize(h.width, kPassX0[p], kPassDx[p]), PassSize(h.height, kPassY0[p], kPassDy[p]));
  return size;
}

// Inflates the IDAT chunks' zlib stream into a scratch buffer, only to check it: that it ends,
// with its Adler-32, exactly where the image data ends, having given exactly the bytes the header
// needs. libspng stops at the last row, so it would not notice a stream cut or corrupted after it.
class ImageDataCheck {
 public:
  explicit ImageDataCheck(const std::string& name) : name_(name) {
    if (inflateInit(&z_) != Z_OK) Refuse(name_, "out of memory");
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
    inflateValidate(&z_, 0);  // as libspng's Adler-32 check is off in the fuzz build
#endif
  }
  ~ImageDataCheck() { inflateEnd(&z_); }
  ImageDataCheck(const ImageDataCheck&) = delete;
  ImageDataCheck& operator=(const ImageDataCheck&) = delete;

  void Expect(std::uint64_t size) { expected_ = size; }

  void Feed(const char* data, std::size_t size) {
    if (ended_) {
      trailing_ += size;
      return;
    }
    z_.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(data));
    z_.avail_in = static_cast<uInt>(size);
    while (z_.avail_in > 0 && !ended_) {
      z_.next_out = scratch_.data();
      z_.avail_out = static_cast<uInt>(scratch_.size());
      const int result = inflate(&z_, Z_NO_FLUSH);
      inflated_ += scratch_.size() - z_.avail_out;
      if (inflated_ > expected_) Refuse(name_, "corrupt: the image data inflates to more than its " + Needs());
      if (result == Z_STREAM_END) {
        ended_ = true;
        trailing_ += z_.avail_in;
      } else if (result == Z_NEED_DICT) {
        Refuse(name_, "corrupt: the image data's zlib stream asks for a preset dictionary");
      } else if (result != Z_OK) {
        Refuse(name_, std::string("corrupt: the image data's zlib stream: ") +
                          (z_.msg != nullptr ? z_.msg : "error " + std::to_string(result)));
      }
    }
  }

  void Finish() const {
    if (!ended_) Refuse(name_, "the image data ends before its zlib stream does (truncated)");
    if (trailing_ > 0)
      Refuse(name_, "corrupt: " + std::to_string(trailing_) + " bytes after the end of the image data's zlib stream");
    if (inflated_ != expected_)
      Refuse(name_, "corrupt: the image data inflates to " + std::to_string(inflated_) + " bytes, not the " + Needs());
  }

 private:
  std::string Needs() const { return std::to_string(expected_) + " bytes its header needs"; }

  std::string name_;
  z_stream z_{};
  std::array<Bytef, 1 << 16> scratch_{};
  std::uint64_t expected_ = 0, inflated_ = 0, trailing_ = 0;
  bool ended_ = false;
};

// Walks the chunks once before libspng decodes anything, for what libspng does not check:
// - every chunk type must be four ASCII letters (PNG spec 5.4); a bad one is shown in hex, never
//   copied to the terminal (libspng skips unknown ancillary chunks unread);
// - the declared size must pass kMaxPngSide and the caller's check, before anything is inflated;
// - the image data's zlib stream is whole and exactly as long as the header needs (ImageDataCheck).
// Whatever else is wrong (no signature, a bad IHDR, a cut-off chunk) is left to libspng to name.
void CheckStructure(std::istream& in, const std::string& name, const PngSizeCheck& check) {
  char header[8];
  if (!in.read(header, 8) || std::string_view(header, 8) != png_format::kSignature) return;
  ImageDataCheck data(name);
  bool have_header = false;
  std::vector<char> piece(std::size_t{1} << 16);
  while (in.read(header, 8)) {
    const bool letters =
        std::all_of(header + 4, header + 8, [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); });
    if (!letters)
      Refuse(name, "corrupt: a chunk type that is not four ASCII letters (bytes " + Hex(header + 4, 4) + ")");
    const std::string_view type(header + 4, 4);
    std::uint32_t length = png_format::BigEndian(header);
    if (type == "IHDR" && !have_header && length == 13) {
      char ihdr[13];
      if (!in.read(ihdr, 13)) return;
      const Header h{png_format::BigEndian(ihdr), png_format::BigEndian(ihdr + 4), static_cast<unsigned char>(ihdr[8]),
                     static_cast<unsigned char>(ihdr[9]), static_cast<unsigned char>(ihdr[12])};
      if (h.width > kMaxPngSide || h.height > kMaxPngSide) Refuse(name, Problem(SPNG_EUSER_WIDTH));
      if (check) check(h.width, h.height);
      data.Expect(FilteredSize(h));
      have_header = true;
      length = 0;
    } else if (type == "IDAT" && have_header) {
      for (std::uint32_t left = length; left > 0;) {
        const std::uint32_t n = std::min<std::uint32_t>(left, static_cast<std::uint32_t>(piece.size()));
        if (!in.read(piece.data(), n)) return;  // cut off: libspng names it
        data.Feed(piece.data(), n);
        left -= n;
      }
      length = 0;
    }
    if (type == "IEND") break;
    if (!in.seekg(std::streamoff{length} + 4, std::ios::cur)) return;
  }
  if (have_header) data.Finish();
}

std::uint32_t ScanlineWidth(const spng_ihdr& ihdr, int pass) {
  return ihdr.interlace_method == 0 ? ihdr.width : PassSize(ihdr.width, kPassX0[pass], kPassDx[pass]);
}

// libspng maps a palette index past the PLTE's last entry to opaque black; such a file is
// corrupt (PNG spec 11.2.3), so every index is read once more, scanline by scanline, and checked.
void CheckPaletteIndices(const Source& source, const std::string& name, const spng_ihdr& ihdr) {
  const Context ctx = NewDecoder(source, name);
  spng_ihdr again{};
  if (const int e = spng_get_ihdr(ctx.get(), &again)) Refuse(name, Problem(e));
  if (again.width != ihdr.width || again.height != ihdr.height || again.bit_depth != ihdr.bit_depth ||
      again.interlace_method != ihdr.interlace_method) {
    Refuse(name, "the file changed while it was being read");
  }
  spng_plte plte{};
  if (const int e = spng_get_plte(ctx.get(), &plte)) Refuse(name, Problem(e));
  std::size_t row_bytes = 0;
  if (const int e = spng_decoded_image_size(ctx.get(), SPNG_FMT_PNG, &row_bytes)) Refuse(name, Problem(e));
  row_bytes /= ihdr.height;
  if (const int e = spng_decode_image(ctx.get(), nullptr, 0, SPNG_FMT_PNG, SPNG_DECODE_PROGRESSIVE))
    Refuse(name, Problem(e));
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
    const std::uint32_t width =
        std::min<std::uint32_t>(ScanlineWidth(ihdr, row.pass), static_cast<std::uint32_t>(scanline.size() * per_byte));
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
  if (std::optional<Image> image = png_fast::Decode(chunks, check)) return std::move(*image);
  chunks.clear();
  chunks.seekg(0);
  CheckStructure(chunks, name, check);
  const Context ctx = NewDecoder(source, name);
  spng_ihdr ihdr{};
  if (const int e = spng_get_ihdr(ctx.get(), &ihdr)) Refuse(name, Problem(e));
  if (check) check(ihdr.width, ihdr.height);
  Image image;
  try {
    image = Image(ihdr.width, ihdr.height);
  } catch (const std::bad_alloc&) {
    Refuse(name, "its " + std::to_string(ihdr.width) + " x " + std::to_string(ihdr.height) + " pixels need " +
                     std::to_string(std::size_t{ihdr.width} * ihdr.height * 4 >> 20) +
                     " MiB, more than this machine gave");
  }
  if (const int e =
          spng_decode_image(ctx.get(), image.rgba.data(), image.rgba.size(), SPNG_FMT_RGBA8, SPNG_DECODE_TRNS)) {
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
  if (!in || !chunks || std::filesystem::is_directory(file, error))
    throw FileError(file.string() + ": cannot open for reading");
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
  return Decode(
      chunks, [&](spng_ctx* ctx) { return spng_set_png_buffer(ctx, bytes.data(), bytes.size()); }, name, check);
}

}  // namespace twinraster
