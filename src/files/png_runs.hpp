// The fastest PNG level's image data: a zlib stream (RFC 1950) of the frame's Up-filtered rows
// (png_scanlines.hpp), deflated (RFC 1951) by looking for only the repeats rendered frames are
// made of: runs of one byte (distance 1) and of one pixel (distance 4), found by comparing 8 bytes
// at a time, with no hash table. A large frame is cut in two halves by rows; each is filtered,
// checksummed and encoded as a block with Huffman codes of its own on its own thread, and the two
// are joined bit for bit. A frame of flat colours and straight edges comes out no larger than
// libdeflate's fastest level makes it, in a fraction of the time. It does not search for
// longer-distance matches (libdeflate's levels do: png_file.hpp).
#pragma once

#include "image/image.hpp"

#include <cstdint>
#include <vector>

namespace twinraster::files::png_runs {

// The zlib stream of `image`'s filtered scanlines: header, deflate blocks and Adler-32.
std::vector<std::uint8_t> ZlibStream(const Image& image);

}  // namespace twinraster::files::png_runs
