// The fast reader against the pixels a PNG was made from: files built here, row by row with each of
// the five filters (PNG spec 9.2, applied here from the spec), deflated by zlib, are read back bit
// for bit by the fast reader and by libspng (the same bytes with an extra chunk, which only libspng
// reads); and every file outside its narrow form is left to libspng.
#include "files/png_fast_reader.hpp"

#include "files/png_file.hpp"
#include "support/catch.hpp"

#include <zlib.h>

#include <cstdlib>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

void PutBigEndian(std::string& out, std::uint32_t v) {
  for (int shift = 24; shift >= 0; shift -= 8) out += static_cast<char>(v >> shift);
}

void PutChunk(std::string& out, const std::string& type, const std::string& data) {
  PutBigEndian(out, static_cast<std::uint32_t>(data.size()));
  const std::string body = type + data;
  out += body;
  PutBigEndian(out, static_cast<std::uint32_t>(
                        crc32(0, reinterpret_cast<const Bytef*>(body.data()), static_cast<uInt>(body.size()))));
}

int Predict(int filter, int a, int b, int c) {
  switch (filter) {
    case 1: return a;
    case 2: return b;
    case 3: return (a + b) / 2;
    case 4: {
      const int p = a + b - c, pa = std::abs(p - a), pb = std::abs(p - b), pc = std::abs(p - c);
      return pa <= pb && pa <= pc ? a : pb <= pc ? b : c;
    }
    default: return 0;
  }
}

// Row y filtered with filter (y + first_filter) % 5, each byte minus its prediction from the
// unfiltered neighbours: a (left), b (above), c (above left).
std::string Filtered(const Image& image, int first_filter) {
  std::string out;
  const std::size_t stride = std::size_t{image.width} * 4;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    const int filter = int((y + std::uint32_t(first_filter)) % 5);
    out += static_cast<char>(filter);
    const std::uint8_t* row = image.rgba.data() + y * stride;
    const std::uint8_t* up = y > 0 ? row - stride : nullptr;
    for (std::size_t i = 0; i < stride; ++i) {
      const int a = i >= 4 ? row[i - 4] : 0, b = up ? up[i] : 0, c = up && i >= 4 ? up[i - 4] : 0;
      out += static_cast<char>(static_cast<std::uint8_t>(row[i] - Predict(filter, a, b, c)));
    }
  }
  return out;
}

std::string Deflated(const std::string& bytes, int level) {
  uLongf size = compressBound(static_cast<uLong>(bytes.size()));
  std::string out(size, '\0');
  REQUIRE(compress2(reinterpret_cast<Bytef*>(out.data()), &size, reinterpret_cast<const Bytef*>(bytes.data()),
                    static_cast<uLong>(bytes.size()), level) == Z_OK);
  out.resize(size);
  return out;
}

struct Form {
  int colour = 6, depth = 8, interlace = 0;
  std::string before{}, after{};  // chunks before the image data, and after it before IEND
  int level = 9;
  int idats = 1;           // the image data cut into this many IDAT chunks
  bool bad_adler = false;  // the zlib stream's checksum one bit off
};

std::string Png(const Image& image, const Form& form, int first_filter = 0) {
  std::string png = "\x89PNG\r\n\x1a\n";
  std::string ihdr;
  PutBigEndian(ihdr, image.width);
  PutBigEndian(ihdr, image.height);
  ihdr += {static_cast<char>(form.depth), static_cast<char>(form.colour), 0, 0, static_cast<char>(form.interlace)};
  PutChunk(png, "IHDR", ihdr);
  png += form.before;
  std::string data = Deflated(Filtered(image, first_filter), form.level);
  if (form.bad_adler) data.back() = static_cast<char>(data.back() ^ 1);
  const std::size_t piece = data.size() / std::size_t(form.idats) + 1;
  for (std::size_t at = 0; at < data.size(); at += piece) PutChunk(png, "IDAT", data.substr(at, piece));
  png += form.after;
  PutChunk(png, "IEND", "");
  return png;
}

std::optional<Image> Fast(const std::string& png) {
  std::istringstream in(png);
  return files::png_fast::Decode(in, {});
}

Image Noise(std::uint32_t width, std::uint32_t height, std::uint32_t seed, int levels) {
  Image image(width, height);
  std::mt19937 random(seed);
  for (std::uint8_t& b : image.rgba)
    b = static_cast<std::uint8_t>(random() % unsigned(levels) * unsigned(255 / (levels - 1)));
  return image;
}

std::string Chunk(const std::string& type, const std::string& data) {
  std::string out;
  PutChunk(out, type, data);
  return out;
}

}  // namespace

TEST_CASE("PNG fast reader: every filter, every row, reads back the pixels it was made from", "[png][reader]") {
  int read = 0;
  for (const auto& [w, h] : {std::pair{1u, 1u}, {1u, 9u}, {2u, 5u}, {13u, 7u}, {640u, 37u}}) {
    for (const int levels : {2, 256}) {  // runs, and noise no filter predicts
      const Image image = Noise(w, h, w * 131 + h, levels);
      for (int first_filter = 0; first_filter < 5; ++first_filter) {
        INFO(w << "x" << h << ", " << levels << " levels, first filter " << first_filter);
        for (const int idats : {1, 3}) {
          const int level = levels == 2 ? 9 : 1;
          const std::string png = Png(image, Form{.level = level, .idats = idats}, first_filter);
          const std::optional<Image> fast = Fast(png);
          const std::size_t data = Deflated(Filtered(image, first_filter), level).size();
          if (data > std::size_t{h} * (4 * w + 1) / 4 + 1024) {
            CHECK_FALSE(fast);  // noise does not deflate to a quarter: left to libspng
          } else {
            REQUIRE(fast);
            CHECK(fast->width == w);
            CHECK(fast->height == h);
            CHECK(fast->rgba == image.rgba);
            ++read;
          }
          // libspng reads the same image data when a chunk it alone reads comes first.
          const std::string spng = Png(image, Form{.before = Chunk("twIn", "x"), .idats = idats}, first_filter);
          CHECK_FALSE(Fast(spng));
          CHECK(files::DecodePng(spng, "spng.png").rgba == image.rgba);
          CHECK(files::DecodePng(png, "png.png").rgba == image.rgba);
        }
      }
    }
  }
  CHECK(read >= 50);
}

TEST_CASE("PNG fast reader: text notes before the image data are read past, as ReadPngNotes keeps them",
          "[png][reader]") {
  const Image image = Noise(16, 16, 7, 2);
  const std::string note = Chunk("tEXt", std::string("twinraster:device\0lavapipe", 26));
  std::optional<Image> fast = Fast(Png(image, Form{.before = note + note}));
  REQUIRE(fast);
  CHECK(fast->rgba == image.rgba);
}

TEST_CASE("PNG fast reader: anything outside its form is left to libspng", "[png][reader]") {
  const Image image = Noise(16, 16, 3, 2);
  const std::string note = Chunk("tEXt", std::string("key\0value", 9));
  const std::string good = Png(image, Form{});
  REQUIRE(Fast(good));
  const std::vector<std::pair<const char*, std::string>> others = {
      {"RGB", Png(image, Form{.colour = 2})},
      {"16 bits", Png(image, Form{.depth = 16})},
      {"interlaced", Png(image, Form{.interlace = 1})},
      {"a chunk of another kind", Png(image, Form{.before = Chunk("gAMA", std::string("\0\0\xb1\x8f", 4))})},
      {"text after the image data", Png(image, Form{.after = note})},
      {"a note with a control character", Png(image, Form{.before = Chunk("tEXt", std::string("key\0a\tb", 7))})},
      {"a note with a bad keyword", Png(image, Form{.before = Chunk("tEXt", std::string(" key\0v", 6))})},
      {"stored, not deflated", Png(Noise(64, 64, 4, 256), Form{.level = 0})},
      {"bytes after IEND", good + "x"},
      {"no IEND", good.substr(0, good.size() - 12)},
      {"a bad CRC", good.substr(0, 29) + static_cast<char>(good[29] ^ 1) + good.substr(30)},
      {"a bad Adler-32", Png(image, Form{.bad_adler = true})},
  };
  for (const auto& [what, png] : others) {
    INFO(what);
    CHECK_FALSE(Fast(png));
  }
}

TEST_CASE("PNG fast reader: the caller's size check runs before anything is inflated", "[png][reader]") {
  const std::string png = Png(Noise(40, 30, 5, 2), Form{});
  std::istringstream in(png);
  CHECK_THROWS_WITH(
      files::png_fast::Decode(in,
                              [](std::uint32_t w, std::uint32_t h) {
                                throw files::FileError("refused " + std::to_string(w) + "x" + std::to_string(h));
                              }),
      "refused 40x30");
}
