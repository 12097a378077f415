// PNG files in and out, with optional text notes: written by a small encoder, over the run encoder
// (png_runs.hpp) at the default level and libdeflate at the others, read by libspng as untrusted input
// (png_reader.cpp: checksums, limits, bounded memory), notes read by a chunk walker of our own.
// Outputs are staged (staged_file.hpp), so a failed run never leaves a truncated PNG or destroys an
// earlier one. It does not keep a PNG's colour space, gamma or bit depth: pixels come back as 8-bit
// RGBA.
#pragma once

#include "files/staged_file.hpp"
#include "image/image.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace twinraster::files {

// Compression levels: 0 stores the pixels uncompressed; 1 (the default), the fastest, is the run
// encoder (png_runs.hpp); 2 to 12 are libdeflate's, 12 the smallest file. Every level is lossless.
inline constexpr int kPngFastest = 1;
inline constexpr int kPngSmallest = 12;

// Text notes as (key, value) pairs, in file order, each one a tEXt chunk between IHDR and IDAT:
// e.g. how the device that rendered the image rasterizes, for `verify` to read back. A key is a PNG
// keyword: 1-79 printable Latin-1 characters, without leading, trailing or double spaces. A value
// is Latin-1 text without NUL; the reader keeps only values of at most 1024 bytes without control
// characters. Writing an invalid note throws std::invalid_argument.
using PngNotes = std::vector<std::pair<std::string, std::string>>;

std::string EncodePng(const Image& image, int level = kPngFastest,
                      const PngNotes& notes = {});  // the bytes of a PNG file
// The bench's comparison: the same file with its image data deflated by libdeflate at `level`
// (0-12), whichever encoder the level usually has.
std::string EncodePngWithLibdeflate(const Image& image, int level);
StagedFile StagePng(const std::filesystem::path& file, const Image& image, int level = kPngFastest,
                    const PngNotes& notes = {});
void WritePng(const std::filesystem::path& file, const Image& image, int level = kPngFastest,
              const PngNotes& notes = {});  // staged and committed at once
// The largest side a PNG may declare: the scene format's largest canvas (scene.hpp's kMaxCanvasSize).
// A larger declaration is refused before anything is decoded.
inline constexpr std::uint32_t kMaxPngSide = 16384;

// Called with the size a PNG declares, after its header and before any pixel is decoded; it throws
// (a FileError naming what it expected) to refuse the file, e.g. against a scene's canvas.
using PngSizeCheck = std::function<void(std::uint32_t width, std::uint32_t height)>;

// Any valid PNG (1 to 16 bits, grey, RGB, palette, with alpha or tRNS, interlaced, in any chunking)
// as 8-bit RGBA; notes ignored. Throws FileError naming the file and the problem for anything else:
// a missing or truncated file, a bad CRC or Adler-32, a palette index past the palette, a side over
// kMaxPngSide, or what `check` refuses. Memory: the image, plus at most about 10 MB.
Image ReadPng(const std::filesystem::path& file, const PngSizeCheck& check = {});
// The same from bytes in memory; `name` is what the messages call them.
Image DecodePng(std::string_view bytes, const std::string& name, const PngSizeCheck& check = {});
// What compare holds whole, at most: an interlaced image (Adam7 spreads each row over seven
// passes, so its rows come only once all are decoded) and the diff image, 4 bytes a pixel: 2^25
// pixels, 128 MiB, an 8K UHD frame (7680 x 4320) and more.
inline constexpr std::uint64_t kMaxWholePixels = std::uint64_t{1} << 25;

// The size a PNG declares, once its signature and IHDR pass the structure check and each side is
// within kMaxPngSide; nothing after IHDR is read. Throws FileError as ReadPng does.
struct PngSize {
  std::uint32_t width = 0, height = 0;
  bool operator==(const PngSize&) const = default;
};
PngSize ReadPngSize(const std::filesystem::path& file);

// A PNG read a row at a time, for a caller that need not hold the image: the same checks as ReadPng
// (the structure check when constructed, every row's as it is decoded, the chunks to IEND and every
// palette index at Finish), each throwing FileError in ReadPng's words. Memory: one row, plus
// libspng's state, for an image over `whole_up_to` pixels; a smaller one is read whole (by default
// 2^22 pixels, 16 MiB: faster, by the fast reader), and so is an interlaced file, refused over
// kMaxWholePixels.
class PngRowReader {
 public:
  static constexpr std::uint64_t kReadWholePixels = std::uint64_t{1} << 22;
  explicit PngRowReader(const std::filesystem::path& file, std::uint64_t whole_up_to = kReadWholePixels);
  ~PngRowReader();
  PngRowReader(const PngRowReader&) = delete;
  PngRowReader& operator=(const PngRowReader&) = delete;

  PngSize Size() const;
  // The next row, Size().width RGBA pixels, valid until the next call; at most Size().height calls.
  const std::uint8_t* NextRow();
  // After the last row: the chunks up to IEND, and a palette image's indices.
  void Finish();

 private:
  struct State;
  std::unique_ptr<State> state_;
};

// The first 64 notes before the pixels whose chunk CRC is right and that pass the rules above;
// the rest are dropped. Never throws on a file's contents: a file that cannot be opened or is not
// a PNG has no notes (ReadPng reports that), and a malformed or cut-off chunk ends the walk.
PngNotes ReadPngNotes(const std::filesystem::path& file);

}  // namespace twinraster::files
