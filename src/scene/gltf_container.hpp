// The bytes around a glTF file's JSON: the .glb container (header, JSON chunk, BIN chunk), and
// the buffers a URI names (base64 data: URIs, and files beside the model); data: URIs for the
// models a scene file carries inline too. It does not parse the
// JSON, and it never follows a URI out of the model's folder or onto the network.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster {

struct GltfContainer {
  std::string_view json;                         // the JSON text (a view into the bytes given)
  std::optional<std::vector<std::uint8_t>> bin;  // a .glb's BIN chunk
};

// True when the bytes start with the .glb magic "glTF".
bool IsGlb(const std::vector<std::uint8_t>& bytes);

// A .glb split into its chunks, or a .gltf's whole text. Throws SceneError naming the byte offset.
GltfContainer SplitGltfContainer(const std::vector<std::uint8_t>& bytes, const std::string& file);

// The bytes a buffer's "uri" names, at most `max_bytes` of them. `where` is the JSON path, for
// errors. A data: URI must be base64; any other URI must be a relative path (percent-encoding
// decoded) that stays inside `directory`. Throws SceneError.
std::vector<std::uint8_t> ReadGltfUri(std::string_view uri, const std::filesystem::path& directory,
                                      std::uint64_t max_bytes, const std::string& file, const std::string& where);

// A data: URI (RFC 2397) decoded: a glTF buffer's, or a scene file's model carried inline.
struct DataUri {
  std::string media_type;  // as written, parameters aside; "" when none is
  bool base64 = false;     // else percent-encoded
  std::vector<std::uint8_t> bytes;
};
bool IsDataUri(std::string_view uri);  // starts with "data:"
// At most `max_bytes` of them; throws SceneError naming `file` and `where` (a JSON path).
DataUri DecodeDataUri(std::string_view uri, std::uint64_t max_bytes, const std::string& file, const std::string& where);

// Reads a whole file of at most `max_bytes`; throws SceneError naming `shown` and `where`.
std::vector<std::uint8_t> ReadFileBytes(const std::filesystem::path& path, std::uint64_t max_bytes,
                                        const std::string& shown, const std::string& where);

}  // namespace twinraster
