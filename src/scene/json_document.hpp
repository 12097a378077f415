// Parses JSON text into a document in one pass, locating every problem: a syntax error by line
// and column, a number out of range or a duplicate key by its JSON path (and lines), and a file
// that is not text at all as such. Any problem is a SceneError. It does not check what the values
// mean: JsonReader does.
#pragma once

#include <nlohmann/json_fwd.hpp>

#include <string>
#include <string_view>

namespace twinraster {

// Deeper nesting than any scene needs; refusing it bounds the work a hostile file can cause.
inline constexpr std::size_t kMaxJsonDepth = 64;

// Refuses text that is not JSON text at all (NUL bytes, or binary data where JSON must start),
// naming the first offending byte.
void RejectBinaryText(std::string_view text, const std::string& file_name);

// How strictly a text is read. kScene refuses a repeated key and nesting deeper than
// kMaxJsonDepth. kGltf takes both as simdjson does (nesting up to kMaxSimdjsonDepth, every field of
// a repeated key kept in order), but where simdjson refuses the text, the problem named is the one
// kScene would name first, as the native build's second parse names it.
enum class JsonStrictness { kScene, kGltf };
inline constexpr std::size_t kMaxSimdjsonDepth = 1024;  // simdjson's default

// `file_name` is only used in error messages. Objects keep their fields in document order.
nlohmann::ordered_json ParseJsonDocument(std::string_view text, const std::string& file_name,
                                         JsonStrictness strictness = JsonStrictness::kScene);

// The same, for text another parser found fault with: throws the located SceneError for any
// problem this parser knows, and returns if it finds none.
void LocateJsonProblem(std::string_view text, const std::string& file_name);

// JSON paths as every scene error prints them: `models.cube.triangles[3][2]`; a key that is not
// an identifier is bracketed and quoted (`models["my cube"]`).
std::string JsonPathKey(const std::string& path, std::string_view key);
std::string JsonPathIndex(const std::string& path, std::size_t index);

}  // namespace twinraster
