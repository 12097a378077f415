// PNG output is lossless at every level: encoded images decode (with libspng, and the fastest
// level's also with zlib) to the same pixels, and higher levels give smaller files. Text notes round trip, and
// reading them survives corrupt, cut-off and hostile files.
#include "files/png_file.hpp"

#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <random>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

// Flat triangles on a background, like a render, plus a band of noise that no filter predicts.
Image TestImage(std::uint32_t width, std::uint32_t height, std::uint32_t seed) {
  Image image(width, height);
  std::mt19937 random(seed);
  for (std::uint32_t y = 0; y < height; ++y) {
    for (std::uint32_t x = 0; x < width; ++x) {
      std::uint8_t* p = image.pixel(x, y);
      if (y % 7 == 3) {
        for (int c = 0; c < 4; ++c) p[c] = static_cast<std::uint8_t>(random());
      } else {
        const bool inside = x * height < y * width;
        p[0] = inside ? 255 : 10, p[1] = static_cast<std::uint8_t>(x), p[2] = static_cast<std::uint8_t>(y), p[3] = 255;
      }
    }
  }
  return image;
}

const files::PngNotes kNotes = {{"twinraster:subPixelPrecisionBits", "8"},
                                {"Device name", "llvmpipe (LLVM 15.0.6, 256 bits)"}};

// Where the first chunk of `type` starts (its length field) in the bytes of a PNG.
std::size_t ChunkAt(const std::string& png, const std::string& type) {
  const std::size_t at = png.find(type);
  REQUIRE(at != std::string::npos);
  return at - 4;
}

void SetBigEndian(std::string& bytes, std::size_t at, std::uint32_t value) {
  for (int i = 0; i < 4; ++i) bytes[at + static_cast<std::size_t>(i)] = static_cast<char>(value >> (24 - 8 * i));
}

}  // namespace

TEST_CASE("PNG round trip: every level decodes to the same pixels", "[png]") {
  const test::TempDir dir;
  for (const auto& [width, height] : {std::pair{1u, 1u}, {3u, 5u}, {640u, 480u}, {1920u, 1080u}}) {
    const Image image = TestImage(width, height, width + height);
    for (const int level : {0, files::kPngFastest, 6, files::kPngSmallest}) {
      INFO(width << "x" << height << " level " << level);
      files::WritePng(dir / "round.png", image, level);
      const Image back = files::ReadPng(dir / "round.png");
      REQUIRE(back.width == image.width);
      REQUIRE(back.height == image.height);
      REQUIRE(back.rgba == image.rgba);
    }
  }
}

namespace {

// The pixels of a PNG written by EncodePng, decoded without libspng: its IDAT chunks inflated by
// zlib, then each row's filter (None or Up, the two the encoder writes) undone here.
std::vector<std::uint8_t> InflateByZlib(const std::string& png, std::uint32_t width, std::uint32_t height) {
  std::string stream;
  for (std::size_t at = 8; at + 12 <= png.size();) {
    std::uint32_t length = 0;
    for (int i = 0; i < 4; ++i) length = (length << 8) | static_cast<std::uint8_t>(png[at + std::size_t(i)]);
    if (png.compare(at + 4, 4, "IDAT") == 0) stream.append(png, at + 8, length);
    at += 12 + length;
  }
  const std::size_t stride = std::size_t{width} * 4;
  std::vector<std::uint8_t> raw((stride + 1) * height + 1);  // one spare byte: more data would show
  uLongf size = raw.size();
  REQUIRE(uncompress(raw.data(), &size, reinterpret_cast<const Bytef*>(stream.data()), stream.size()) == Z_OK);
  REQUIRE(size == (stride + 1) * height);
  std::vector<std::uint8_t> pixels(stride * height);
  for (std::size_t y = 0; y < height; ++y) {
    const std::uint8_t filter = raw[(stride + 1) * y];
    REQUIRE((filter == 0 || filter == 2));
    for (std::size_t i = 0; i < stride; ++i) {
      const std::uint8_t above = (filter == 2 && y > 0) ? pixels[stride * (y - 1) + i] : 0;
      pixels[stride * y + i] = static_cast<std::uint8_t>(raw[(stride + 1) * y + 1 + i] + above);
    }
  }
  return pixels;
}

}  // namespace

TEST_CASE("PNG at the fastest level: zlib and libspng, two decoders of their own, read back every pixel", "[png]") {
  std::mt19937 random(20261126u);
  std::vector<Image> images;
  images.push_back(TestImage(1, 1, 1));
  images.push_back(TestImage(3, 7, 2));
  images.push_back(TestImage(1920, 1080, 3));  // large enough to be cut in two blocks
  Image noise(700, 500);                       // nothing repeats: literals only
  for (std::uint8_t& b : noise.rgba) b = static_cast<std::uint8_t>(random());
  images.push_back(noise);
  Image flat(1200, 900);  // one colour: runs only, across the two blocks' seam
  for (std::size_t i = 0; i < flat.rgba.size(); ++i) flat.rgba[i] = static_cast<std::uint8_t>(i % 4 == 3 ? 255 : 200);
  images.push_back(flat);
  Image stripes(1001, 1000);  // period 4 and period 1 runs, odd width
  for (std::size_t i = 0; i < stripes.rgba.size(); ++i)
    stripes.rgba[i] = static_cast<std::uint8_t>((i / 4096) % 2 ? i % 4 * 60 : 77);
  images.push_back(stripes);
  for (const Image& image : images) {
    INFO(image.width << "x" << image.height);
    const std::string png = files::EncodePng(image, files::kPngFastest);
    CHECK(std::ranges::equal(InflateByZlib(png, image.width, image.height), image.rgba));
    CHECK(files::DecodePng(png, "fast.png").rgba == image.rgba);
  }
}

TEST_CASE("PNG levels: 0 stores, higher levels are no larger", "[png]") {
  const Image image = TestImage(640, 480, 7);
  const std::size_t stored = files::EncodePng(image, 0).size();
  const std::size_t fastest = files::EncodePng(image, files::kPngFastest).size();
  const std::size_t smallest = files::EncodePng(image, files::kPngSmallest).size();
  REQUIRE(stored > image.rgba.size());  // the filtered scanlines, uncompressed, plus headers
  REQUIRE(fastest < stored);
  REQUIRE(smallest <= fastest);
}

TEST_CASE("PNG: a level outside 0..12 and an empty image are refused", "[png]") {
  REQUIRE_THROWS_AS(files::EncodePng(TestImage(2, 2, 1), -1), std::invalid_argument);
  REQUIRE_THROWS_AS(files::EncodePng(TestImage(2, 2, 1), 13), std::invalid_argument);
  REQUIRE_THROWS_AS(files::EncodePng(Image()), std::invalid_argument);
}

TEST_CASE("PNG notes: two notes round trip, written between IHDR and IDAT", "[png]") {
  const test::TempDir dir;
  files::WritePng(dir / "notes.png", TestImage(3, 2, 1), files::kPngFastest, kNotes);
  REQUIRE(files::ReadPngNotes(dir / "notes.png") == kNotes);
  const std::string png = test::ReadFile(dir / "notes.png");
  REQUIRE(png.find("IHDR") < png.find("tEXt"));
  REQUIRE(png.rfind("tEXt") < png.find("IDAT"));

  files::WritePng(dir / "plain.png", TestImage(3, 2, 1));
  REQUIRE(files::ReadPngNotes(dir / "plain.png").empty());
  REQUIRE(test::ReadFile(dir / "plain.png") == files::EncodePng(TestImage(3, 2, 1)));  // no notes, no tEXt chunk
  REQUIRE(test::ReadFile(dir / "plain.png").find("tEXt") == std::string::npos);
}

TEST_CASE("PNG notes survive StagePng and Commit", "[png]") {
  const test::TempDir dir;
  files::StagedFile staged = files::StagePng(dir / "staged.png", TestImage(4, 4, 2), files::kPngSmallest, kNotes);
  REQUIRE(!std::filesystem::exists(dir / "staged.png"));
  staged.Commit();
  REQUIRE(files::ReadPngNotes(dir / "staged.png") == kNotes);
}

TEST_CASE("PNG notes: an image with notes decodes to exactly the same pixels", "[png]") {
  const test::TempDir dir;
  const Image image = TestImage(640, 480, 3);
  files::WritePng(dir / "notes.png", image, files::kPngFastest, kNotes);
  const Image back = files::ReadPng(dir / "notes.png");
  REQUIRE(back.width == image.width);
  REQUIRE(back.height == image.height);
  REQUIRE(back.rgba == image.rgba);
}

TEST_CASE("PNG notes: a tEXt chunk with a wrong CRC is skipped, and the image refused", "[png]") {
  const test::TempDir dir;
  std::string png = files::EncodePng(TestImage(2, 2, 4), files::kPngFastest, kNotes);
  const std::size_t first = ChunkAt(png, "tEXt");
  const std::uint32_t length = static_cast<std::uint32_t>(kNotes[0].first.size() + 1 + kNotes[0].second.size());
  png[first + 8 + length] ^= 1;  // the first byte of its CRC
  test::WriteFile(dir / "crc.png", png);
  REQUIRE(files::ReadPngNotes(dir / "crc.png") == files::PngNotes{kNotes[1]});
  // The image reader takes the file as corrupt: no verdict on it (png_reader_test.cpp).
  REQUIRE_THROWS_WITH(files::ReadPng(dir / "crc.png"),
                      HasSubstring("crc.png: cannot read as PNG: corrupt: invalid chunk checksum"));
}

TEST_CASE("PNG notes: a cut-off file or an absurd chunk length ends the walk, keeping what came before", "[png]") {
  const test::TempDir dir;
  const std::string png = files::EncodePng(TestImage(2, 2, 5), files::kPngFastest, kNotes);
  const std::size_t second = ChunkAt(png, "tEXt") + 12 + kNotes[0].first.size() + 1 + kNotes[0].second.size();
  for (std::size_t size = 0; size <= png.size(); ++size) {
    INFO("cut at " << size << " of " << png.size() << " bytes");
    test::WriteFile(dir / "cut.png", png.substr(0, size));
    const files::PngNotes notes = files::ReadPngNotes(dir / "cut.png");
    const std::size_t complete = size >= ChunkAt(png, "IDAT") ? 2 : size >= second ? 1 : 0;
    REQUIRE(notes == files::PngNotes(kNotes.begin(), kNotes.begin() + static_cast<std::ptrdiff_t>(complete)));
  }
  for (const std::uint32_t length : {0x7fffffffu, 0x80000000u, 0xffffffffu, static_cast<std::uint32_t>(png.size())}) {
    INFO("length " << length);
    std::string absurd = png;
    SetBigEndian(absurd, second, length);
    test::WriteFile(dir / "absurd.png", absurd);
    REQUIRE(files::ReadPngNotes(dir / "absurd.png") == files::PngNotes{kNotes[0]});
  }
}

TEST_CASE("PNG notes: a file that is not a PNG, or is missing, has none", "[png]") {
  const test::TempDir dir;
  test::WriteFile(dir / "text.png", "not a PNG, though long enough to hold a signature and a chunk");
  REQUIRE(files::ReadPngNotes(dir / "text.png").empty());
  REQUIRE(files::ReadPngNotes(dir / "missing.png").empty());
  REQUIRE(files::ReadPngNotes(dir.path()).empty());  // a directory
}

TEST_CASE("PNG notes: a value with a control character is dropped", "[png]") {
  const test::TempDir dir;
  const files::PngNotes notes = {{"tab", "a\tb"}, {"newline", "a\nb"}, {"delete", "a\x7f"}, {"kept", "Latin-1 \xe9"}};
  files::WritePng(dir / "control.png", TestImage(2, 2, 6), files::kPngFastest, notes);
  REQUIRE(files::ReadPngNotes(dir / "control.png") == files::PngNotes{{"kept", "Latin-1 \xe9"}});
}

TEST_CASE("PNG notes: at most 64 are read, each value at most 1024 bytes", "[png]") {
  const test::TempDir dir;
  files::PngNotes notes = {{"long", std::string(1025, 'x')}, {"longest", std::string(1024, 'x')}};
  for (int i = 0; i < 70; ++i) notes.emplace_back("n" + std::to_string(i), std::to_string(i));
  files::WritePng(dir / "many.png", TestImage(2, 2, 7), files::kPngFastest, notes);
  const files::PngNotes back = files::ReadPngNotes(dir / "many.png");
  REQUIRE(back.size() == 64);
  REQUIRE(back.front() == notes[1]);
  REQUIRE(back.back() == notes[64]);
}

TEST_CASE("PNG notes: an invalid key or a NUL in a value is refused", "[png]") {
  const Image image = TestImage(2, 2, 8);
  for (const std::string& key :
       {std::string(), std::string(80, 'k'), std::string(" lead"), std::string("trail "), std::string("double  space"),
        std::string("new\nline"), std::string("del\x7f"), std::string("nul\0", 4), std::string("c1 \x85")}) {
    INFO("key \"" << key << "\"");
    REQUIRE_THROWS_AS(files::EncodePng(image, files::kPngFastest, {{key, "v"}}), std::invalid_argument);
  }
  REQUIRE_THROWS_AS(files::EncodePng(image, files::kPngFastest, {{"key", std::string("a\0b", 3)}}),
                    std::invalid_argument);
  REQUIRE_NOTHROW(files::EncodePng(image, files::kPngFastest, {{std::string(79, 'k'), ""}, {"one space \xe9", "v"}}));
}
