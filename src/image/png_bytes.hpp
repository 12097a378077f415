// The byte-level facts of the PNG format that the writer, the notes walker and the reader share:
// the signature and big-endian 32-bit fields (PNG spec 5.2, 5.3). It reads and writes no chunk.
#pragma once

#include <cstdint>
#include <string_view>

namespace twinraster::png_format {

inline constexpr std::string_view kSignature{"\x89PNG\r\n\x1a\n", 8};

inline std::uint32_t BigEndian(const char* bytes) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value = value << 8 | static_cast<unsigned char>(bytes[i]);
  return value;
}

}  // namespace twinraster::png_format
