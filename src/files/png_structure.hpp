// The one structure check every PNG read makes before anything is decoded, over a file or bytes in
// memory alike: it sizes its input first and never reads or seeks past the end, so a file and the
// same bytes in memory are refused with the same words, naming the first thing wrong in file
// order. It decodes no pixel (libspng does, png_reader.cpp) and checks no chunk's contents but
// IHDR's.
#pragma once

#include "files/png_file.hpp"

#include <cstdint>
#include <istream>
#include <string>

namespace twinraster::files::png_structure {

// What IHDR declares, checked: the sides, bit depth, colour type and interlace method.
struct Header {
  std::uint32_t width = 0, height = 0;
  unsigned depth = 0, colour = 0, interlace = 0;
};

// The width of Adam7's pass `pass` (0 to 6) of an image `width` pixels wide.
std::uint32_t PassWidth(std::uint32_t width, int pass);

// Throws FileError "NAME: cannot read as PNG: PROBLEM".
[[noreturn]] void Refuse(const std::string& name, const std::string& problem);
// The words for a file that ends too soon, and for a side over kMaxPngSide: the reader uses them too.
std::string Truncated();
std::string SideOverLimit();

// The signature and IHDR, from the start of `in`: IHDR first, 13 bytes of valid fields (PNG spec
// 11.2.2), its CRC right; then each side at most kMaxPngSide, then `check`. Leaves `in` after IHDR.
Header CheckHeader(std::istream& in, const std::string& name, const PngSizeCheck& check);

// CheckHeader, then every chunk: a type of four ASCII letters (shown in hex otherwise, never
// copied to the terminal), a length within the PNG limit and within the file, IEND reached; and
// the image data's zlib stream inflated into a scratch buffer and thrown away, which must end, its
// Adler-32 right, exactly where the image data does, after exactly the bytes the header needs.
Header CheckStructure(std::istream& in, const std::string& name, const PngSizeCheck& check);

}  // namespace twinraster::files::png_structure
