// Inside the glTF reader (gltf_*.cpp): the reading of each top-level array of a glTF 2.0 document
// into GltfDocument, each checking what it reads and the indices it follows. Not for other stages:
// they take the GltfDocument.
#pragma once

#include "scene/gltf_document.hpp"
#include "scene/json_reader.hpp"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace twinraster::gltf {

// An index into one of the document's arrays: an integer in [0, size), or the reader's error
// naming the array.
std::size_t ReadIndex(const JsonReader& r, std::size_t size, std::string_view array);

// The array under `key` (absent: empty), refusing more than limits.objects entries.
std::optional<JsonReader> ReadArray(const JsonReader& root, std::string_view key, const GltfLimits& limits);

// Each top-level array in turn; later ones check their indices against earlier ones.
void ReadMaterials(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc);
void ReadMeshes(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc);
void ReadCameras(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc);
// Nodes and scenes: each node has at most one parent, no cycle, no deeper than limits.node_depth;
// a scene lists roots only.
void ReadNodesAndScenes(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc);

// "a + b" and "a * b" that refuse to wrap: false on overflow.
bool AddChecked(std::uint64_t a, std::uint64_t b, std::uint64_t& sum);
bool MultiplyChecked(std::uint64_t a, std::uint64_t b, std::uint64_t& product);

}  // namespace twinraster::gltf
