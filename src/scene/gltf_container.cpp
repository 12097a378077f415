#include "scene/gltf_container.hpp"

#include "scene/scene_error.hpp"

#include <array>
#include <cstring>
#include <fstream>

namespace twinraster {

namespace {

constexpr std::uint32_t kGlbMagic = 0x46546C67;   // "glTF"
constexpr std::uint32_t kJsonChunk = 0x4E4F534A;  // "JSON"
constexpr std::uint32_t kBinChunk = 0x004E4942;   // "BIN\0"
constexpr std::size_t kGlbHeaderBytes = 12, kChunkHeaderBytes = 8;

std::uint32_t LittleEndian32(const std::vector<std::uint8_t>& bytes, std::size_t at) {
  return std::uint32_t{bytes[at]} | std::uint32_t{bytes[at + 1]} << 8 | std::uint32_t{bytes[at + 2]} << 16 |
         std::uint32_t{bytes[at + 3]} << 24;
}

[[noreturn]] void FailAt(const std::string& file, std::size_t byte, const std::string& problem) {
  throw SceneError(file, "byte " + std::to_string(byte), problem);
}

std::string_view Text(const std::vector<std::uint8_t>& bytes, std::size_t at, std::size_t length) {
  return {reinterpret_cast<const char*>(bytes.data()) + at, length};
}

int Base64Value(char c) {
  if (c >= 'A' && c <= 'Z') return c - 'A';
  if (c >= 'a' && c <= 'z') return c - 'a' + 26;
  if (c >= '0' && c <= '9') return c - '0' + 52;
  if (c == '+' || c == '-') return 62;  // '-' and '_': the URL-safe alphabet some exporters write
  if (c == '/' || c == '_') return 63;
  return -1;
}

std::vector<std::uint8_t> DecodeBase64(std::string_view text, std::uint64_t max_bytes, const std::string& file,
                                       const std::string& where) {
  while (!text.empty() && text.back() == '=') text.remove_suffix(1);
  if (text.size() / 4 * 3 > max_bytes) {
    throw SceneError(file, where, "the data: URI holds more than " + std::to_string(max_bytes) + " bytes");
  }
  std::vector<std::uint8_t> out;
  out.reserve(text.size() / 4 * 3 + 3);
  std::uint32_t bits = 0;
  int count = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    const int value = Base64Value(text[i]);
    if (value < 0) {
      throw SceneError(file, where, "the data: URI's base64 has an invalid character at position " + std::to_string(i));
    }
    bits = bits << 6 | static_cast<std::uint32_t>(value);
    if (++count == 4) {
      out.push_back(static_cast<std::uint8_t>(bits >> 16));
      out.push_back(static_cast<std::uint8_t>(bits >> 8));
      out.push_back(static_cast<std::uint8_t>(bits));
      bits = 0;
      count = 0;
    }
  }
  if (count == 1) throw SceneError(file, where, "the data: URI's base64 is truncated");
  if (count == 2) out.push_back(static_cast<std::uint8_t>(bits >> 4));
  if (count == 3) {
    out.push_back(static_cast<std::uint8_t>(bits >> 10));
    out.push_back(static_cast<std::uint8_t>(bits >> 2));
  }
  return out;
}

int HexValue(char c) {
  if (c >= '0' && c <= '9') return c - '0';
  if (c >= 'a' && c <= 'f') return c - 'a' + 10;
  if (c >= 'A' && c <= 'F') return c - 'A' + 10;
  return -1;
}

// A relative URI reference as a relative path: percent-decoded, and refused when it could name a
// file outside the model's folder (absolute, a scheme, "..", a backslash or a NUL).
std::filesystem::path RelativeUriPath(std::string_view uri, const std::string& file, const std::string& where) {
  const auto refuse = [&](const std::string& why) {
    throw SceneError(file, where, "the URI \"" + std::string(uri.substr(0, 200)) + "\" is refused: " + why);
  };
  if (uri.empty()) refuse("it is empty");
  const std::size_t colon = uri.find(':'), slash = uri.find('/');
  if (colon != std::string_view::npos && (slash == std::string_view::npos || colon < slash)) {
    refuse("it has a scheme; only data: URIs and paths relative to the model are read");
  }
  std::string decoded;
  for (std::size_t i = 0; i < uri.size(); ++i) {
    if (uri[i] != '%') {
      decoded += uri[i];
      continue;
    }
    const int high = i + 2 < uri.size() ? HexValue(uri[i + 1]) : -1,
              low = i + 2 < uri.size() ? HexValue(uri[i + 2]) : -1;
    if (high < 0 || low < 0) refuse("a '%' is not followed by two hexadecimal digits");
    decoded += static_cast<char>(high * 16 + low);
    i += 2;
  }
  if (decoded.find('\0') != std::string::npos) refuse("it holds a NUL byte");
  if (decoded.find('\\') != std::string::npos) refuse("it holds a backslash");
  if (decoded.front() == '/') refuse("it is absolute");
  const std::filesystem::path path(decoded);
  for (const auto& part : path) {
    if (part == "..") refuse("it leaves the model's folder (\"..\")");
  }
  if (path.has_root_path()) refuse("it is absolute");
  return path;
}

}  // namespace

bool IsGlb(const std::vector<std::uint8_t>& bytes) {
  return bytes.size() >= 4 && LittleEndian32(bytes, 0) == kGlbMagic;
}

GltfContainer SplitGltfContainer(const std::vector<std::uint8_t>& bytes, const std::string& file) {
  if (!IsGlb(bytes)) return {Text(bytes, 0, bytes.size()), std::nullopt};
  if (bytes.size() < kGlbHeaderBytes + kChunkHeaderBytes) FailAt(file, 0, "a .glb shorter than its headers");
  const std::uint32_t version = LittleEndian32(bytes, 4), length = LittleEndian32(bytes, 8);
  if (version != 2) {
    FailAt(file, 4, "a .glb of version " + std::to_string(version) + "; twinraster reads glTF 2.0 (version 2)");
  }
  if (length > bytes.size()) {
    FailAt(file, 8,
           "the header says " + std::to_string(length) + " bytes, the file has " + std::to_string(bytes.size()));
  }
  GltfContainer out;
  bool have_json = false;
  std::size_t at = kGlbHeaderBytes;
  while (at < length) {
    if (length - at < kChunkHeaderBytes) FailAt(file, at, "a chunk header is cut off by the end of the file");
    const std::uint32_t chunk_length = LittleEndian32(bytes, at), type = LittleEndian32(bytes, at + 4);
    const std::size_t data = at + kChunkHeaderBytes;
    if (chunk_length > length - data) {
      FailAt(file, at, "a chunk of " + std::to_string(chunk_length) + " bytes runs past the end of the file");
    }
    if (!have_json) {
      if (type != kJsonChunk) FailAt(file, at + 4, "the first chunk is not JSON");
      out.json = Text(bytes, data, chunk_length);
      have_json = true;
    } else if (type == kBinChunk) {
      if (out.bin) FailAt(file, at + 4, "a second BIN chunk");
      out.bin.emplace(bytes.begin() + static_cast<std::ptrdiff_t>(data),
                      bytes.begin() + static_cast<std::ptrdiff_t>(data + chunk_length));
    } else if (type == kJsonChunk) {
      FailAt(file, at + 4, "a second JSON chunk");
    }  // any other chunk type: skipped, as the spec asks
    at = data + chunk_length;
  }
  if (!have_json) FailAt(file, kGlbHeaderBytes, "no JSON chunk");
  return out;
}

std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path, std::uint64_t max_bytes,
                                        const std::string& shown, const std::string& where) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec)) throw SceneError(shown, where, "is a directory, not a file");
  if (!std::filesystem::exists(path, ec)) throw SceneError(shown, where, "no such file");
  if (!std::filesystem::is_regular_file(path, ec)) throw SceneError(shown, where, "not a regular file");
  const std::uintmax_t size = std::filesystem::file_size(path, ec);
  if (ec) throw SceneError(shown, where, "cannot read the file: " + ec.message());
  if (size > max_bytes) {
    throw SceneError(shown, where, "larger than " + std::to_string(max_bytes >> 20) + " MiB: refused");
  }
  std::ifstream in(path, std::ios::binary);
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(size));
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()))) {
    throw SceneError(shown, where, "cannot read the file");
  }
  return bytes;
}

bool IsDataUri(std::string_view uri) { return uri.starts_with("data:"); }

DataUri DecodeDataUri(std::string_view uri, std::uint64_t max_bytes, const std::string& file,
                      const std::string& where) {
  const std::size_t comma = uri.find(',');
  if (comma == std::string_view::npos) throw SceneError(file, where, "a data: URI without a comma");
  std::string_view header = uri.substr(0, comma).substr(std::string_view("data:").size());
  DataUri out;
  constexpr std::string_view kBase64 = ";base64";
  out.base64 = header.ends_with(kBase64);
  if (out.base64) header.remove_suffix(kBase64.size());
  out.media_type = std::string(header.substr(0, header.find(';')));  // parameters (charset) aside
  const std::string_view data = uri.substr(comma + 1);
  if (out.base64) {
    out.bytes = DecodeBase64(data, max_bytes, file, where);
    return out;
  }
  // Percent-encoded (RFC 3986): every other byte stands for itself.
  if (data.size() > max_bytes) {
    throw SceneError(file, where, "the data: URI holds more than " + std::to_string(max_bytes) + " bytes");
  }
  out.bytes.reserve(data.size());
  for (std::size_t i = 0; i < data.size(); ++i) {
    if (data[i] != '%') {
      out.bytes.push_back(static_cast<std::uint8_t>(data[i]));
      continue;
    }
    const int high = i + 2 < data.size() ? HexValue(data[i + 1]) : -1,
              low = i + 2 < data.size() ? HexValue(data[i + 2]) : -1;
    if (high < 0 || low < 0) {
      throw SceneError(file, where,
                       "the data: URI's '%' at character " + std::to_string(comma + 2 + i) +
                           " is not followed by two hexadecimal digits");
    }
    out.bytes.push_back(static_cast<std::uint8_t>(high * 16 + low));
    i += 2;
  }
  return out;
}

std::vector<std::uint8_t> ReadGltfUri(std::string_view uri, const std::filesystem::path& directory,
                                      std::uint64_t max_bytes, const std::string& file, const std::string& where) {
  if (IsDataUri(uri)) {
    const std::size_t comma = uri.find(',');
    if (comma == std::string_view::npos) throw SceneError(file, where, "a data: URI without a comma");
    if (!uri.substr(0, comma).ends_with(";base64")) throw SceneError(file, where, "a data: URI that is not base64");
    return DecodeDataUri(uri, max_bytes, file, where).bytes;
  }
  const std::filesystem::path relative = RelativeUriPath(uri, file, where);
  if (directory.empty()) {
    throw SceneError(file, where, "the URI \"" + std::string(uri) + "\" names a file, and none may be read here");
  }
  const std::filesystem::path path = directory / relative;
  return ReadFileBytes(path, max_bytes, file, where + " (\"" + path.string() + "\")");
}

}  // namespace twinraster
