// What tests that write glTF files byte by byte share: little-endian values, base64 for data:
// URIs, and a .glb container around a JSON text and a BIN chunk, laid out as the glTF 2.0 spec's
// "Binary glTF Layout" says. It does not check what it wraps: the reader under test does.
#pragma once

#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace twinraster::test {

template <class T>
void AppendBytes(std::vector<std::uint8_t>& bytes, T value) {
  std::uint8_t raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));  // the machines twinraster builds on are little-endian
  bytes.insert(bytes.end(), raw, raw + sizeof(T));
}

// RFC 4648's base64, with '=' padding.
inline std::string Base64(const std::vector<std::uint8_t>& bytes) {
  static const char* kAlphabet = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string out;
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::uint32_t b1 = i + 1 < bytes.size() ? bytes[i + 1] : 0, b2 = i + 2 < bytes.size() ? bytes[i + 2] : 0;
    const std::uint32_t word = std::uint32_t{bytes[i]} << 16 | b1 << 8 | b2;
    out += kAlphabet[word >> 18 & 63];
    out += kAlphabet[word >> 12 & 63];
    out += i + 1 < bytes.size() ? kAlphabet[word >> 6 & 63] : '=';
    out += i + 2 < bytes.size() ? kAlphabet[word & 63] : '=';
  }
  return out;
}

// A data: URI holding `bytes`.
inline std::string DataUri(const std::vector<std::uint8_t>& bytes) {
  return "data:application/octet-stream;base64," + Base64(bytes);
}

// The 12-byte header, the JSON chunk (padded with spaces) and the BIN chunk.
inline std::vector<std::uint8_t> Glb(std::string json, const std::vector<std::uint8_t>& bin) {
  while (json.size() % 4) json += ' ';
  std::vector<std::uint8_t> glb;
  AppendBytes(glb, std::uint32_t{0x46546C67});  // "glTF"
  AppendBytes(glb, std::uint32_t{2});
  AppendBytes(glb, static_cast<std::uint32_t>(12 + 8 + json.size() + 8 + bin.size()));
  AppendBytes(glb, static_cast<std::uint32_t>(json.size()));
  AppendBytes(glb, std::uint32_t{0x4E4F534A});  // "JSON"
  glb.insert(glb.end(), json.begin(), json.end());
  AppendBytes(glb, static_cast<std::uint32_t>(bin.size()));
  AppendBytes(glb, std::uint32_t{0x004E4942});  // "BIN\0"
  glb.insert(glb.end(), bin.begin(), bin.end());
  return glb;
}

}  // namespace twinraster::test
