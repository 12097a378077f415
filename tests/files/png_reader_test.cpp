// The PNG reader on files from elsewhere (tests/files/pngs/, scripts/make-test-pngs.py): every
// valid encoding reads as the same pixels, every malformed file is refused with the file's name and
// a reason, and nothing from the file reaches the message as a control character.
#include "files/png_file.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <algorithm>
#include <array>
#include <filesystem>
#include <map>
#include <string>

using namespace twinraster;

namespace {

std::filesystem::path Png(const std::string& folder, const std::string& name) {
  return test::SourcePath("tests/files/pngs/" + folder + "/" + name);
}

// The message ReadPng throws for a file, or "" if it reads it.
std::string Refusal(const std::filesystem::path& file, const files::PngSizeCheck& check = {}) {
  try {
    files::ReadPng(file, check);
    return "";
  } catch (const files::FileError& e) {
    return e.what();
  }
}

bool HasControlCharacter(const std::string& text) {
  return std::any_of(text.begin(), text.end(),
                     [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

// Which reference each valid file must equal: the same picture, in its colour type's own terms.
std::string ReferenceOf(const std::string& name) {
  if (name.starts_with("grey1.") || name.starts_with("grey1-")) return "grey1.png";
  if (name.starts_with("grey-alpha")) return "grey-alpha8.png";
  if (name.starts_with("grey")) return "grey8.png";
  if (name.starts_with("rgb8") || name.starts_with("rgb16")) return "rgb8.png";
  return "rgba8.png";
}

}  // namespace

TEST_CASE("PNG reader: every valid encoding of the picture reads as the same RGBA", "[png][reader]") {
  const Image rgba = files::ReadPng(Png("valid", "rgba8.png"));
  REQUIRE(rgba.width == 13);
  REQUIRE(rgba.height == 7);
  // The picture, by hand: bands of red, blue, green and clear white, a band every 4 columns and 3 rows.
  CHECK(std::equal(rgba.pixel(0, 0), rgba.pixel(0, 0) + 4, std::array<std::uint8_t, 4>{255, 0, 0, 255}.begin()));
  CHECK(std::equal(rgba.pixel(12, 6), rgba.pixel(12, 6) + 4, std::array<std::uint8_t, 4>{0, 128, 255, 255}.begin()));
  CHECK(rgba.pixel(4, 6)[3] == 0);  // (4 / 4 + 6 / 3) % 4 == 3: the clear band
  int read = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::SourcePath("tests/files/pngs/valid"))) {
    const std::string name = entry.path().filename().string();
    INFO(name << " against " << ReferenceOf(name));
    const Image image = files::ReadPng(entry.path());
    const Image reference = files::ReadPng(Png("valid", ReferenceOf(name)));
    CHECK(image.width == reference.width);
    CHECK(image.height == reference.height);
    CHECK(image.rgba == reference.rgba);
    ++read;
  }
  CHECK(read == 27);  // every file scripts/make-test-pngs.py writes there
}

TEST_CASE("PNG reader: every malformed file is refused, naming the file and the problem", "[png][reader]") {
  // A part of each reason: enough to show it is the right one.
  const std::map<std::string, std::string> reasons = {
      {"bad-adler32.png", "corrupt: the image data's zlib stream: incorrect data check"},
      {"bad-adler32-split.png", "corrupt: the image data's zlib stream: incorrect data check"},
      {"data-after-zlib-stream.png", "corrupt: 4 bytes after the end of the image data's zlib stream"},
      {"bad-filter-type.png", "corrupt: invalid scanline filter"},
      {"bomb-16384-truncated.png", "refused: 16384 x 16384"},
      {"chunk-type-with-escape.png", "not four ASCII letters (bytes 61 1b 5b 31)"},
      {"deflate-reserved-block.png", "corrupt: the image data's zlib stream: invalid block type"},
      {"empty-first-idat-only.png", "the image data ends before its zlib stream does"},
      {"empty.png", "truncated"},
      {"idat-bad-crc.png", "corrupt: invalid chunk checksum"},
      {"ihdr-bad-crc.png", "corrupt: invalid chunk checksum"},
      {"idat-length-over-2-31.png", "corrupt: chunk exceeds maximum standard length"},
      {"no-iend.png", "truncated"},
      {"not-a-png.png", "not a PNG file"},
      {"palette-index-out-of-range.png", "palette index 3 in row 0, but the palette has 2 entries"},
      {"palette1-interlaced-index-out-of-range.png", "palette index 1 in row 6, but the palette has 1 entries"},
      {"side-over-limit.png", "declares a side over 16384 pixels"},
      {"signature-only.png", "truncated"},
      {"too-little-data.png", "corrupt: the image data inflates to 100 bytes, not the 371 bytes its header needs"},
      {"truncated-in-idat.png", "truncated"},
      {"ztxt-bomb.png", "an ancillary chunk holds more than twinraster keeps"},
      {"ihdr-colour-type-5.png", "corrupt: IHDR declares colour type 5 (a PNG's is 0, 2, 3, 4 or 6)"},
      {"ihdr-bit-depth-7.png", "corrupt: IHDR declares bit depth 7 (a PNG's is 1, 2, 4, 8 or 16)"},
      {"ihdr-palette-16-bit.png", "corrupt: IHDR declares bit depth 16 with colour type 3, which allows 1, 2, 4 or 8"},
      {"ihdr-cut-after-colour-type-5.png", "corrupt: IHDR declares colour type 5"},
      {"text-past-the-end.png", "cannot read as PNG: the file ends before the PNG does (truncated)"},
  };
  // Like verify's canvas check: a size is refused before anything is decoded (the bomb would be
  // 1 GiB of RGBA).
  const files::PngSizeCheck canvas = [](std::uint32_t w, std::uint32_t h) {
    if (w > 1024 || h > 1024) throw files::FileError("refused: " + std::to_string(w) + " x " + std::to_string(h));
  };
  int refused = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::SourcePath("tests/files/pngs/malformed"))) {
    const std::string name = entry.path().filename().string();
    INFO(name);
    REQUIRE(reasons.contains(name));
    const std::string message = Refusal(entry.path(), canvas);
    CHECK_THAT(message, HasSubstring(reasons.at(name)));
    if (!message.starts_with("refused")) {
      CHECK(message.starts_with(entry.path().string() + ": cannot read as PNG: "));
      CHECK(message.size() > (entry.path().string() + ": cannot read as PNG: ").size());
    }
    CHECK_FALSE(HasControlCharacter(message));
    ++refused;
  }
  CHECK(refused == static_cast<int>(reasons.size()));
}

TEST_CASE("PNG reader: bytes in memory are read as a file is, and refused as a file is", "[png][reader]") {
  const std::string good = test::ReadFile(Png("valid", "palette4.png"));
  CHECK(files::DecodePng(good, "palette4.png").rgba == files::ReadPng(Png("valid", "rgba8.png")).rgba);
  const std::string bad = test::ReadFile(Png("malformed", "palette-index-out-of-range.png"));
  CHECK_THROWS_WITH(files::DecodePng(bad, "bytes"),
                    HasSubstring("bytes: cannot read as PNG: corrupt: palette index 3"));
  CHECK_THROWS_WITH(files::DecodePng("", "nothing"), HasSubstring("nothing: cannot read as PNG: the file ends"));
}

TEST_CASE("PNG reader: every malformed file is refused in the same words from a file and from memory",
          "[png][reader]") {
  // One structure check for both: reading a file it could seek past the end, which a buffer cannot.
  int compared = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::SourcePath("tests/files/pngs/malformed"))) {
    const std::string file = entry.path().string();
    INFO(file);
    const std::string from_file = Refusal(entry.path());
    std::string from_memory;
    try {
      files::DecodePng(test::ReadFile(entry.path()), file);
    } catch (const files::FileError& e) {
      from_memory = e.what();
    }
    CHECK_FALSE(from_file.empty());
    CHECK(from_file == from_memory);
    ++compared;
  }
  CHECK(compared == 26);
}

namespace {

// The image PngRowReader gives, row by row (none read whole but the interlaced), or the message it
// throws.
std::pair<Image, std::string> ReadRows(const std::filesystem::path& file) {
  try {
    files::PngRowReader rows(file, 0);
    Image image(rows.Size().width, rows.Size().height);
    for (std::uint32_t y = 0; y < image.height; ++y)
      std::copy_n(rows.NextRow(), std::size_t{image.width} * 4, image.pixel(0, y));
    rows.Finish();
    return {image, ""};
  } catch (const files::FileError& e) {
    return {Image(), e.what()};
  }
}

}  // namespace

TEST_CASE(
    "PNG reader: a row at a time, every valid file reads as ReadPng reads it, and every malformed one is refused "
    "in its words",
    "[png][reader]") {
  int read = 0;
  for (const char* folder : {"valid", "malformed"}) {
    for (const auto& entry : std::filesystem::directory_iterator(test::SourcePath("tests/files/pngs/") / folder)) {
      INFO(entry.path().string());
      const auto [image, message] = ReadRows(entry.path());
      CHECK(message == Refusal(entry.path()));
      if (message.empty()) {
        CHECK(image.rgba == files::ReadPng(entry.path()).rgba);
        CHECK(files::ReadPngSize(entry.path()) == files::PngSize{image.width, image.height});
      }
      ++read;
    }
  }
  CHECK(read == 27 + 26);
}

TEST_CASE("PNG reader: a row at a time, a file that declares 16384 x 16384 pixels gives its rows one by one",
          "[png][reader]") {
  const auto file = Png("large", "declares-16384x16384.png");
  CHECK(files::ReadPngSize(file) == files::PngSize{16384, 16384});
  files::PngRowReader rows(file);
  REQUIRE(rows.Size() == files::PngSize{16384, 16384});
  // Its first and last rows: black and opaque (1-bit grey 0).
  const std::uint8_t* first = rows.NextRow();
  CHECK((first[0] == 0 && first[3] == 255 && first[16383 * 4 + 3] == 255));
  // An interlaced file is decoded whole, so one over kMaxWholePixels is refused before anything is.
  const auto interlaced = Png("large", "interlaced-8192x4097.png");
  CHECK_THROWS_WITH(files::PngRowReader(interlaced),
                    interlaced.string() +
                        ": cannot read as PNG: an interlaced PNG is decoded whole, and its 8192 x 4097 "
                        "pixels are over the 33554432 twinraster holds whole (write it without "
                        "interlacing)");
  // The rest is `compare`'s test (tests/cli/verify_cli_test.cpp), which measures its memory.
}

TEST_CASE("PNG reader: a missing file or a folder is named, not decoded", "[png][reader]") {
  const test::TempDir dir;
  CHECK_THAT(Refusal(dir / "missing.png"), HasSubstring("missing.png: cannot open for reading"));
  CHECK_THAT(Refusal(dir.path()), HasSubstring(": cannot open for reading"));
}
