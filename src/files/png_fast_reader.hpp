// The PNGs renderers write, read without libspng: 8-bit RGBA, not interlaced, with at most text
// notes beside the image data, which deflates well. libdeflate inflates the image data in one call
// (zlib, which libspng uses, inflates it row by row and copies runs byte by byte: most of what
// `verify` spent on a twinraster PNG), and the five filters are undone here, in place in the image.
// It refuses nothing and names no problem: any file outside that narrow form, or any doubt (a bad
// CRC, a stream that is not exactly the image), is left to the full reader (png_reader.cpp), which
// then reads it, or names what is wrong, as before.
#pragma once

#include "files/png_file.hpp"
#include "image/image.hpp"

#include <istream>
#include <optional>

namespace twinraster::files::png_fast {

// The image, or nothing when the full reader must decide. Reads `in` from its start; `check` runs
// on the declared size before anything is inflated, as the full reader runs it, and may throw.
std::optional<Image> Decode(std::istream& in, const PngSizeCheck& check);

}  // namespace twinraster::files::png_fast
