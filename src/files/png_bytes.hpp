// The byte-level facts of the PNG format that the writer, the notes walker and the readers share:
// the signature, big-endian 32-bit fields and the longest chunk (PNG spec 5.2, 5.3), what a tEXt
// keyword may hold (11.3.4.3), and how much of the notes twinraster keeps. It reads and writes no
// chunk.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <string_view>

namespace twinraster::files::png_format {

inline constexpr std::string_view kSignature{"\x89PNG\r\n\x1a\n", 8};

inline std::uint32_t BigEndian(const char* bytes) {
  std::uint32_t value = 0;
  for (int i = 0; i < 4; ++i) value = value << 8 | static_cast<unsigned char>(bytes[i]);
  return value;
}

inline constexpr std::uint32_t kMaxChunkLength = 0x7fffffff;

inline constexpr std::size_t kMaxKeyword = 79;
// The notes kept: the first 64, each value at most 1024 bytes (png_file.hpp).
inline constexpr std::size_t kMaxNotes = 64;
inline constexpr std::size_t kMaxNoteValue = 1024;

// Latin-1's printable characters, the space included: what a keyword is made of.
inline bool IsPrintableLatin1(char c) {
  const auto b = static_cast<unsigned char>(c);
  return (b >= 0x20 && b <= 0x7e) || b >= 0xa1;
}

// A tEXt keyword: 1 to 79 printable Latin-1 characters, spaces single and inside.
inline bool IsValidKeyword(std::string_view key) {
  if (key.empty() || key.size() > kMaxKeyword || key.front() == ' ' || key.back() == ' ') return false;
  return key.find("  ") == std::string_view::npos && std::all_of(key.begin(), key.end(), IsPrintableLatin1);
}

}  // namespace twinraster::files::png_format
