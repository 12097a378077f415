// PNG files in and out, with optional text notes: written by a small encoder, over the run encoder
// (png_runs.hpp) at the default level and libdeflate at the others, read by libspng as untrusted input
// (png_reader.cpp: checksums, limits, bounded memory), notes read by a chunk walker of our own.
// Outputs are staged (staged_file.hpp), so a failed run never leaves a truncated PNG or destroys an
// earlier one. It does not keep a PNG's colour space, gamma or bit depth: pixels come back as 8-bit
// RGBA.
#pragma once

#include "image/image.hpp"
#include "image/staged_file.hpp"

#include <cstdint>
#include <filesystem>
#include <functional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace twinraster {

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
// The first 64 notes before the pixels whose chunk CRC is right and that pass the rules above;
// the rest are dropped. Never throws on a file's contents: a file that cannot be opened or is not
// a PNG has no notes (ReadPng reports that), and a malformed or cut-off chunk ends the walk.
PngNotes ReadPngNotes(const std::filesystem::path& file);

}  // namespace twinraster
