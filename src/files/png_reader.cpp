// ReadPng and DecodePng: PNG files from anywhere (any GPU, any engine, a bug report), read with
// libspng, which checks every chunk's CRC and the zlib stream's Adler-32 and has limits, unless
// the file is of the narrow form renderers write, which png_fast_reader.hpp reads faster. Nothing is
// decoded before png_structure.hpp's check passes (the declared size within kMaxPngSide and the
// caller's check among it), which names the first thing wrong, file or memory alike; the only large
// allocation is the RGBA image itself (and, read by the fast reader, the image data, at most 8 MiB
// of it); a file is otherwise streamed, never read whole.
#include "files/png_bytes.hpp"
#include "files/png_fast_reader.hpp"
#include "files/png_file.hpp"
#include "files/png_structure.hpp"

#include <spng.h>

#include <algorithm>
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

namespace twinraster::files {
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

using png_structure::Refuse;

// libspng's own words for its error codes are static English; none comes from the file.
std::string Problem(int error) {
  switch (error) {
    case SPNG_IO_EOF:
    case SPNG_EIO: return png_structure::Truncated();
    case SPNG_IO_ERROR: return "a read error";
    case SPNG_ESIGNATURE: return "not a PNG file (its first 8 bytes are not the PNG signature)";
    case SPNG_EUSER_WIDTH:
    case SPNG_EUSER_HEIGHT: return png_structure::SideOverLimit();
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

std::uint32_t ScanlineWidth(const spng_ihdr& ihdr, int pass) {
  return ihdr.interlace_method == 0 ? ihdr.width : png_structure::PassWidth(ihdr.width, pass);
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
  png_structure::CheckStructure(chunks, name, check);
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
using File = std::unique_ptr<std::FILE, FileClose>;

// Opens the file twice, for libspng and for the structure check; refuses a folder or nothing.
File OpenPng(const std::filesystem::path& file, std::ifstream& chunks) {
  File in(std::fopen(file.c_str(), "rb"));
  chunks.open(file, std::ios::binary);
  std::error_code error;
  if (!in || !chunks || std::filesystem::is_directory(file, error))
    throw FileError(file.string() + ": cannot open for reading");
  return in;
}

}  // namespace

Image ReadPng(const std::filesystem::path& file, const PngSizeCheck& check) {
  std::ifstream chunks;
  const File in = OpenPng(file, chunks);
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

}  // namespace twinraster::files

namespace twinraster::files {

PngSize ReadPngSize(const std::filesystem::path& file) {
  std::ifstream chunks;
  OpenPng(file, chunks);
  const png_structure::Header h = png_structure::CheckHeader(chunks, file.string(), {});
  return {h.width, h.height};
}

struct PngRowReader::State {
  std::string name;
  File file;
  Source source;
  Context ctx;
  spng_ihdr ihdr{};
  std::optional<Image> whole;  // an interlaced file, deinterlaced
  std::vector<std::uint8_t> row;
  std::uint32_t next = 0;
};

PngRowReader::PngRowReader(const std::filesystem::path& file, std::uint64_t whole_up_to)
    : state_(std::make_unique<State>()) {
  State& s = *state_;
  s.name = file.string();
  std::ifstream chunks;
  s.file = OpenPng(file, chunks);
  const png_structure::Header h = png_structure::CheckHeader(chunks, s.name, {});
  const std::uint64_t pixels = std::uint64_t{h.width} * h.height;
  if (h.interlace != 0 && pixels > kMaxWholePixels) {
    Refuse(s.name, "an interlaced PNG is decoded whole, and its " + std::to_string(h.width) + " x " +
                       std::to_string(h.height) + " pixels are over the " + std::to_string(kMaxWholePixels) +
                       " twinraster holds whole (write it without interlacing)");
  }
  // A small image is read whole, by the fast reader when it can: a render's rows cost more one by
  // one through libspng than the whole image held (16 MiB at most).
  if (h.interlace != 0 || pixels <= whole_up_to) {
    s.whole = ReadPng(file);
    return;
  }
  png_structure::CheckStructure(chunks, s.name, {});
  std::FILE* in = s.file.get();
  s.source = [in](spng_ctx* ctx) {
    std::rewind(in);
    return spng_set_png_file(ctx, in);
  };
  s.ctx = NewDecoder(s.source, s.name);
  if (const int e = spng_get_ihdr(s.ctx.get(), &s.ihdr)) Refuse(s.name, Problem(e));
  if (const int e =
          spng_decode_image(s.ctx.get(), nullptr, 0, SPNG_FMT_RGBA8, SPNG_DECODE_TRNS | SPNG_DECODE_PROGRESSIVE))
    Refuse(s.name, Problem(e));
  s.row.resize(std::size_t{s.ihdr.width} * 4);
}

PngRowReader::~PngRowReader() = default;

PngSize PngRowReader::Size() const {
  const State& s = *state_;
  return s.whole ? PngSize{s.whole->width, s.whole->height} : PngSize{s.ihdr.width, s.ihdr.height};
}

const std::uint8_t* PngRowReader::NextRow() {
  State& s = *state_;
  if (s.next >= Size().height) throw std::logic_error("PngRowReader::NextRow past the last row");
  if (s.whole) return s.whole->pixel(0, s.next++);
  // SPNG_EOI comes with the last row, written like the others.
  const int e = spng_decode_row(s.ctx.get(), s.row.data(), s.row.size());
  if (e != 0 && e != SPNG_EOI) Refuse(s.name, Problem(e));
  ++s.next;
  return s.row.data();
}

void PngRowReader::Finish() {
  State& s = *state_;
  if (s.whole) return;  // ReadPng checked it all
  if (const int e = spng_decode_chunks(s.ctx.get())) Refuse(s.name, Problem(e));
  if (s.ihdr.color_type == SPNG_COLOR_TYPE_INDEXED) CheckPaletteIndices(s.source, s.name, s.ihdr);
}

}  // namespace twinraster::files
