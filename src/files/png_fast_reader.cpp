#include "files/png_fast_reader.hpp"

#include "files/png_bytes.hpp"

#include <libdeflate.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <new>
#include <string>
#include <string_view>

namespace twinraster::files::png_fast {
namespace {

using png_format::kMaxChunkLength, png_format::kMaxNotes, png_format::kMaxNoteValue;
constexpr std::size_t kMaxNoteBytes = png_format::kMaxKeyword + 1 + kMaxNoteValue;  // keyword, NUL, value
constexpr std::size_t kMaxImageData = std::size_t{8} << 20;                         // bytes of IDAT held at once

struct DecompressorFree {
  void operator()(libdeflate_decompressor* d) const { libdeflate_free_decompressor(d); }
};

// A chunk's type and data, read whole with its CRC checked (not under libFuzzer, as in the full
// reader, so that mutated inputs reach the decoder).
bool ReadChunkData(std::istream& in, std::string_view type, std::uint32_t length, std::string& data) {
  data.resize(std::size_t{length} + 4);
  if (!in.read(data.data(), std::streamsize(data.size()))) return false;
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
  (void)type;
#else
  const std::uint32_t crc = libdeflate_crc32(libdeflate_crc32(0, type.data(), 4), data.data(), length);
  if (crc != png_format::BigEndian(data.data() + length)) return false;
#endif
  data.resize(length);
  return true;
}

// A note this reader accepts: a valid keyword, and a value of printable Latin-1 alone, which no
// PNG reader refuses. Any other text chunk is the full reader's to judge.
bool PlainNote(std::string_view data) {
  const std::size_t nul = data.find('\0');
  if (nul == std::string_view::npos || !png_format::IsValidKeyword(data.substr(0, nul))) return false;
  const std::string_view value = data.substr(nul + 1);
  return value.size() <= kMaxNoteValue && std::all_of(value.begin(), value.end(), png_format::IsPrintableLatin1);
}

// What the header declares, when it is the one form this reader decodes: 8-bit RGBA (colour type
// 6), deflate, the adaptive filters, no interlacing, each side 1 to kMaxPngSide.
bool RgbaHeader(std::string_view ihdr, std::uint32_t& width, std::uint32_t& height) {
  width = png_format::BigEndian(ihdr.data()), height = png_format::BigEndian(ihdr.data() + 4);
  const bool sides = width >= 1 && height >= 1 && width <= kMaxPngSide && height <= kMaxPngSide;
  return sides && ihdr[8] == 8 && ihdr[9] == 6 && ihdr[10] == 0 && ihdr[11] == 0 && ihdr[12] == 0;
}

int Paeth(int a, int b, int c) {  // PNG spec 9.4: the neighbour nearest a + b - c, ties to a, then b
  const int pa = std::abs(b - c), pb = std::abs(a - c), pc = std::abs(a + b - 2 * c);
  return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
}

// Undoes one row's filter (PNG spec 9.2): `up` is the row above, unfiltered, or null for the first
// row, whose missing neighbours are zeros; the first pixel's missing left neighbours likewise.
// Each case is its own loop, so that Up (twinraster's filter) vectorizes.
bool UnfilterRow(int filter, const std::uint8_t* in, std::uint8_t* out, const std::uint8_t* up, std::size_t stride) {
  const std::size_t first = std::min<std::size_t>(4, stride);
  switch (filter) {
    case 0:
      for (std::size_t i = 0; i < stride; ++i) out[i] = in[i];
      return true;
    case 1:
      for (std::size_t i = 0; i < first; ++i) out[i] = in[i];
      for (std::size_t i = 4; i < stride; ++i) out[i] = std::uint8_t(in[i] + out[i - 4]);
      return true;
    case 2:
      if (!up) return UnfilterRow(0, in, out, up, stride);
      for (std::size_t i = 0; i < stride; ++i) out[i] = std::uint8_t(in[i] + up[i]);
      return true;
    case 3:
      for (std::size_t i = 0; i < first; ++i) out[i] = std::uint8_t(in[i] + (up ? up[i] / 2 : 0));
      for (std::size_t i = 4; i < stride; ++i) out[i] = std::uint8_t(in[i] + (out[i - 4] + (up ? up[i] : 0)) / 2);
      return true;
    case 4:
      if (!up) return UnfilterRow(1, in, out, up, stride);                           // Paeth(a, 0, 0) is a
      for (std::size_t i = 0; i < first; ++i) out[i] = std::uint8_t(in[i] + up[i]);  // Paeth(0, b, 0) is b
      for (std::size_t i = 4; i < stride; ++i) out[i] = std::uint8_t(in[i] + Paeth(out[i - 4], up[i], up[i - 4]));
      return true;
    default: return false;
  }
}

// Undoes every row's filter, moving the rows down over their filter bytes so that `bytes` ends as
// the RGBA image (row y's filtered bytes always lie after where it goes: read before written);
// false for a filter type past 4.
bool Unfilter(std::uint8_t* bytes, std::uint32_t width, std::uint32_t height) {
  const std::size_t stride = std::size_t{width} * 4;
  for (std::size_t y = 0; y < height; ++y) {
    const std::uint8_t* in = bytes + y * (stride + 1);  // the row's filter type, then its bytes
    std::uint8_t* out = bytes + y * stride;
    if (!UnfilterRow(in[0], in + 1, out, y > 0 ? out - stride : nullptr, stride)) return false;
  }
  return true;
}

// Inflates the zlib stream into exactly `out`, checking its Adler-32, with no byte of it left
// over; then undoes the filters in place.
std::optional<Image> Inflate(const std::string& stream, std::uint32_t width, std::uint32_t height) {
  const std::unique_ptr<libdeflate_decompressor, DecompressorFree> d(libdeflate_alloc_decompressor());
  if (!d) return std::nullopt;
  Image image;
  const std::size_t filtered = std::size_t{height} * (std::size_t{width} * 4 + 1);
  try {
    image.rgba = FrameVector<std::uint8_t>(filtered);  // shrunk to the image below, in place
  } catch (const std::bad_alloc&) {
    return std::nullopt;  // the full reader says how much was needed
  }
  std::size_t used = 0, made = 0;
  const libdeflate_result r =
      libdeflate_zlib_decompress_ex(d.get(), stream.data(), stream.size(), image.rgba.data(), filtered, &used, &made);
  if (r != LIBDEFLATE_SUCCESS || used != stream.size() || made != filtered) return std::nullopt;
  if (!Unfilter(image.rgba.data(), width, height)) return std::nullopt;
  image.rgba.resize(std::size_t{width} * height * 4);
  image.width = width, image.height = height;
  return image;
}

}  // namespace

std::optional<Image> Decode(std::istream& in, const PngSizeCheck& check) {
  char head[8];
  if (!in.read(head, 8) || std::string_view(head, 8) != png_format::kSignature) return std::nullopt;
  std::string data, stream;
  std::uint32_t width = 0, height = 0;
  std::size_t notes = 0;
  bool header = false, image_data = false;
  while (in.read(head, 8)) {
    const std::uint32_t length = png_format::BigEndian(head);
    const std::string_view type(head + 4, 4);
    if (length > kMaxChunkLength) return std::nullopt;
    if (!header) {  // IHDR first, always
      if (type != "IHDR" || length != 13 || !ReadChunkData(in, type, length, data)) return std::nullopt;
      if (!RgbaHeader(data, width, height)) return std::nullopt;
      if (check) check(width, height);
      header = true;
    } else if (type == "IDAT") {
      // Renderers' images deflate to far less than a quarter, and 8 MiB holds a 1080p frame's many
      // times over: more is held in memory beside the image only by the full reader, which streams.
      const std::size_t limit = std::min(std::size_t{height} * (std::size_t{width} * 4 + 1) / 4 + 1024, kMaxImageData);
      if (stream.size() + length > limit || !ReadChunkData(in, type, length, data)) return std::nullopt;
      stream += data;
      image_data = true;
    } else if (type == "IEND") {
      if (!image_data || length != 0 || !ReadChunkData(in, type, length, data)) return std::nullopt;
      if (in.peek() != std::char_traits<char>::eof()) return std::nullopt;  // bytes after the PNG
      return Inflate(stream, width, height);
    } else if (type == "tEXt" && !image_data && ++notes <= kMaxNotes && length <= kMaxNoteBytes) {
      if (!ReadChunkData(in, type, length, data) || !PlainNote(data)) return std::nullopt;
    } else {
      return std::nullopt;  // any other chunk, or one after the image data but IEND: the full reader's
    }
  }
  return std::nullopt;  // no IEND
}

}  // namespace twinraster::files::png_fast
