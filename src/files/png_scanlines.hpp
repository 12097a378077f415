// The filtered scanlines a PNG's image data compresses (PNG spec, 7.2 and 9): each row a filter
// byte, then the row with the Up filter (each byte minus the byte above). It does not choose a
// filter per row or compress anything (png_file.hpp, png_runs.hpp).
#pragma once

#include "image/image.hpp"

#include <cstddef>
#include <cstdint>

namespace twinraster::files::png_scanlines {

// The bytes of one filtered row: the filter byte and 4 per pixel.
inline std::size_t RowBytes(const Image& image) { return std::size_t{image.width} * 4 + 1; }

// Rows [first, last) of `image`, filtered, written to `out` (RowBytes each). Rows are independent
// (Up reads the image, not the output), so parts of a frame can be filtered on different threads.
void FilterRows(const Image& image, std::uint32_t first, std::uint32_t last, std::uint8_t* out);

}  // namespace twinraster::files::png_scanlines
