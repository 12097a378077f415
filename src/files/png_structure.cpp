#include "files/png_structure.hpp"

#include "files/png_bytes.hpp"

#include <libdeflate.h>
#include <spng.h>
#include <zlib.h>

#include <algorithm>
#include <array>
#include <string_view>
#include <vector>

namespace twinraster::files::png_structure {
namespace {

#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
constexpr bool kCheckCrc = false;  // as in png_reader.cpp: mutated inputs reach the decoder
#else
constexpr bool kCheckCrc = true;
#endif

// Adam7's passes: where each starts and how far apart its pixels are, across and down.
constexpr std::uint32_t kPassX0[7] = {0, 4, 0, 2, 0, 1, 0};
constexpr std::uint32_t kPassDx[7] = {8, 8, 4, 4, 2, 2, 1};
constexpr std::uint32_t kPassY0[7] = {0, 0, 4, 0, 2, 0, 1};
constexpr std::uint32_t kPassDy[7] = {8, 8, 8, 4, 4, 2, 2};

std::uint32_t PassSize(std::uint32_t size, std::uint32_t start, std::uint32_t step) {
  return size > start ? (size - start + step - 1) / step : 0;
}

// libspng's words for an error code: static English, nothing from the file.
std::string SpngWords(int error) { return std::string("corrupt: ") + spng_strerror(error); }

// The input, sized first: reads stop at its end and skips never pass it, so a file and a string
// stream (which cannot seek past its end, where a file can) behave alike.
class Input {
 public:
  explicit Input(std::istream& in) : in_(in) {
    in_.clear();
    in_.seekg(0, std::ios::end);
    const std::streamoff end = in_.tellg();
    in_.seekg(0);
    left_ = end > 0 ? static_cast<std::uint64_t>(end) : 0;
  }
  std::uint64_t Left() const { return left_; }
  // Reads up to `size` bytes; returns how many it read.
  std::size_t Read(char* out, std::size_t size) {
    in_.read(out, static_cast<std::streamsize>(std::min<std::uint64_t>(size, left_)));
    const auto got = static_cast<std::size_t>(in_.gcount());
    left_ -= got;
    return got;
  }
  void Skip(std::uint64_t size) {  // size <= Left()
    in_.seekg(static_cast<std::streamoff>(size), std::ios::cur);
    left_ -= size;
  }

 private:
  std::istream& in_;
  std::uint64_t left_ = 0;
};

std::string Hex(const char* bytes, std::size_t size) {
  static const char kDigits[] = "0123456789abcdef";
  std::string text;
  for (std::size_t i = 0; i < size; ++i) {
    const auto b = static_cast<unsigned char>(bytes[i]);
    text += (i ? " " : "") + std::string{kDigits[b >> 4], kDigits[b & 15]};
  }
  return text;
}

// A chunk's type, when it is four ASCII letters (PNG spec 5.4); refused in hex otherwise.
std::string_view ChunkType(const char* head, const std::string& name) {
  const bool letters =
      std::all_of(head + 4, head + 8, [](char c) { return (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z'); });
  if (!letters) Refuse(name, "corrupt: a chunk type that is not four ASCII letters (bytes " + Hex(head + 4, 4) + ")");
  return {head + 4, 4};
}

// The bit depths each colour type allows (PNG spec 11.2.2, table 11.1), as text; empty for none.
std::string DepthsAllowed(unsigned colour) {
  switch (colour) {
    case 0: return "1, 2, 4, 8 or 16";
    case 3: return "1, 2, 4 or 8";
    case 2:
    case 4:
    case 6: return "8 or 16";
    default: return "";
  }
}

bool DepthAllowed(unsigned depth, unsigned colour) {
  if (colour == 3 && depth == 16) return false;
  return colour == 0 || colour == 3 || depth >= 8;
}

// IHDR's fields, in file order, as far as `size` of its 13 bytes go: the first one wrong is named.
void CheckFields(const unsigned char* f, std::size_t size, const std::string& name) {
  const auto refuse = [&](const std::string& what) { Refuse(name, "corrupt: IHDR declares " + what); };
  for (int side = 0; side < 2 && size >= 4 * std::size_t(side) + 4; ++side) {
    const std::uint32_t value = png_format::BigEndian(reinterpret_cast<const char*>(f) + 4 * side);
    if (value == 0 || value > png_format::kMaxChunkLength)
      refuse(std::string(side ? "a height" : "a width") + " of " + std::to_string(value) +
             " (a PNG's is 1 to 2^31 - 1)");
  }
  const unsigned depth = f[8], colour = f[9];
  if (size > 8 && depth != 1 && depth != 2 && depth != 4 && depth != 8 && depth != 16)
    refuse("bit depth " + std::to_string(depth) + " (a PNG's is 1, 2, 4, 8 or 16)");
  if (size > 9 && DepthsAllowed(colour).empty())
    refuse("colour type " + std::to_string(colour) + " (a PNG's is 0, 2, 3, 4 or 6)");
  if (size > 9 && !DepthAllowed(depth, colour))
    refuse("bit depth " + std::to_string(depth) + " with colour type " + std::to_string(colour) + ", which allows " +
           DepthsAllowed(colour));
  if (size > 10 && f[10] != 0) refuse("compression method " + std::to_string(f[10]) + " (a PNG's is 0)");
  if (size > 11 && f[11] != 0) refuse("filter method " + std::to_string(f[11]) + " (a PNG's is 0)");
  if (size > 12 && f[12] > 1) refuse("interlace method " + std::to_string(f[12]) + " (a PNG's is 0 or 1)");
}

Header HeaderOf(Input& input, const std::string& name, const PngSizeCheck& check) {
  char signature[8];
  const std::size_t got = input.Read(signature, 8);
  if (std::string_view(signature, got) != png_format::kSignature.substr(0, got))
    Refuse(name, "not a PNG file (its first 8 bytes are not the PNG signature)");
  char head[8];
  if (got < 8 || input.Read(head, 8) < 8) Refuse(name, Truncated());
  const std::string_view type = ChunkType(head, name);
  if (type != "IHDR") Refuse(name, "corrupt: the first chunk is " + std::string(type) + ", not IHDR");
  const std::uint32_t length = png_format::BigEndian(head);
  if (length != 13) Refuse(name, "corrupt: IHDR holds " + std::to_string(length) + " bytes, not 13");
  char ihdr[13 + 4] = {};
  const std::size_t fields = input.Read(ihdr, 13);
  CheckFields(reinterpret_cast<const unsigned char*>(ihdr), fields, name);
  if (fields < 13 || input.Read(ihdr + 13, 4) < 4) Refuse(name, Truncated());
  if (kCheckCrc && libdeflate_crc32(libdeflate_crc32(0, "IHDR", 4), ihdr, 13) != png_format::BigEndian(ihdr + 13))
    Refuse(name, SpngWords(SPNG_ECHUNK_CRC));
  const Header h{png_format::BigEndian(ihdr), png_format::BigEndian(ihdr + 4), static_cast<unsigned char>(ihdr[8]),
                 static_cast<unsigned char>(ihdr[9]), static_cast<unsigned char>(ihdr[12])};
  if (h.width > kMaxPngSide || h.height > kMaxPngSide) Refuse(name, SideOverLimit());
  if (check) check(h.width, h.height);
  return h;
}

// The bytes the image data must inflate to: each row's filter byte and samples, for the whole
// image or for each of Adam7's passes (PNG spec 7.2, 8.2).
std::uint64_t FilteredSize(const Header& h) {
  const unsigned channels = h.colour == 2 ? 3 : h.colour == 4 ? 2 : h.colour == 6 ? 4 : 1;
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
  ImageDataCheck(const std::string& name, std::uint64_t expected) : name_(name), expected_(expected) {
    if (inflateInit(&z_) != Z_OK) Refuse(name_, "out of memory");
#ifdef FUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION
    inflateValidate(&z_, 0);  // as libspng's Adler-32 check is off in the fuzz build
#endif
  }
  ~ImageDataCheck() { inflateEnd(&z_); }
  ImageDataCheck(const ImageDataCheck&) = delete;
  ImageDataCheck& operator=(const ImageDataCheck&) = delete;

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

}  // namespace

std::uint32_t PassWidth(std::uint32_t width, int pass) { return PassSize(width, kPassX0[pass], kPassDx[pass]); }

void Refuse(const std::string& name, const std::string& problem) {
  throw FileError(name + ": cannot read as PNG: " + problem);
}

std::string Truncated() { return "the file ends before the PNG does (truncated)"; }

std::string SideOverLimit() {
  return "it declares a side over " + std::to_string(kMaxPngSide) + " pixels, the most twinraster reads";
}

Header CheckHeader(std::istream& in, const std::string& name, const PngSizeCheck& check) {
  Input input(in);
  return HeaderOf(input, name, check);
}

Header CheckStructure(std::istream& in, const std::string& name, const PngSizeCheck& check) {
  Input input(in);
  const Header h = HeaderOf(input, name, check);
  ImageDataCheck data(name, FilteredSize(h));
  bool image_data = false;
  std::vector<char> piece(std::size_t{1} << 16);
  for (;;) {
    char head[8];
    if (input.Read(head, 8) < 8) {
      if (image_data) data.Finish();  // a fault in the stream comes before the missing end
      Refuse(name, Truncated());
    }
    const std::string_view type = ChunkType(head, name);
    const std::uint32_t length = png_format::BigEndian(head);
    if (length > png_format::kMaxChunkLength) Refuse(name, SpngWords(SPNG_ECHUNK_STDLEN));
    if (std::uint64_t{length} + 4 > input.Left()) Refuse(name, Truncated());
    if (type == "IDAT") {
      for (std::uint32_t left = length; left > 0;) {
        const std::uint32_t n = std::min<std::uint32_t>(left, static_cast<std::uint32_t>(piece.size()));
        input.Read(piece.data(), n);  // within the file: checked above
        data.Feed(piece.data(), n);
        left -= n;
      }
      input.Skip(4);
      image_data = true;
      continue;
    }
    input.Skip(std::uint64_t{length} + 4);
    if (type == "IEND") {
      data.Finish();
      return h;
    }
  }
}

}  // namespace twinraster::files::png_structure
