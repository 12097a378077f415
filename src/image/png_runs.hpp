// A deflate encoder for the filtered scanlines of rendered frames (RFC 1951), fast because it
// looks for only the repeats such frames are made of: runs of one byte (distance 1) and of one
// pixel (distance 4), found by comparing 8 bytes at a time, with no hash table. A large input is
// cut in two blocks, each with Huffman codes built for it, encoded on two threads and joined bit
// for bit. A frame of flat colours and straight edges comes out no larger than libdeflate's
// fastest level makes it, in a fraction of the time. It does not search for longer-distance
// matches (libdeflate's levels do: png_file.hpp), and it does not write the zlib header or
// checksum.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace twinraster::png_runs {

// The deflate stream of `data`, one final block, appended to `out`.
void Deflate(std::span<const std::uint8_t> data, std::vector<std::uint8_t>& out);

}  // namespace twinraster::png_runs
