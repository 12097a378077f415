#include "scene/gltf_document.hpp"

#include "base/counted.hpp"
#include "scene/gltf_container.hpp"
#include "scene/gltf_parse.hpp"
#include "scene/json_document.hpp"
#include "scene/json_value.hpp"
#include "scene/scene_error.hpp"

#include <algorithm>
#include <array>

namespace twinraster::gltf {

std::size_t ReadIndex(const JsonReader& r, std::size_t size, std::string_view array) {
  if (size == 0) r.Fail("names an entry of \"" + std::string(array) + "\", but the file has none");
  return static_cast<std::size_t>(r.Integer(0, static_cast<std::int64_t>(size) - 1));
}

std::optional<JsonReader> ReadArray(const JsonReader& root, std::string_view key, const GltfLimits& limits) {
  std::optional<JsonReader> array = root.Find(key);
  if (!array) return std::nullopt;
  if (array->IsObject()) {
    array->Fail("an object, as glTF 1.0 writes it; twinraster reads glTF 2.0, where this is an array");
  }
  if (array->ExpectArray() > limits.objects) {
    array->Fail("more than " + std::to_string(limits.objects) + " entries: refused");
  }
  return array;
}

bool AddChecked(std::uint64_t a, std::uint64_t b, std::uint64_t& sum) { return !__builtin_add_overflow(a, b, &sum); }
bool MultiplyChecked(std::uint64_t a, std::uint64_t b, std::uint64_t& product) {
  return !__builtin_mul_overflow(a, b, &product);
}

}  // namespace twinraster::gltf

namespace twinraster {

namespace {

using gltf::ReadArray;
using gltf::ReadIndex;

// Extensions twinraster draws; a file that requires any other is refused, as the spec asks.
constexpr std::array<std::string_view, 1> kImplementedExtensions = {"KHR_materials_unlit"};

bool Implemented(std::string_view name) {
  return std::find(kImplementedExtensions.begin(), kImplementedExtensions.end(), name) != kImplementedExtensions.end();
}

void ReadAsset(const JsonReader& root, GltfDocument& doc) {
  const std::optional<JsonReader> asset = root.Find("asset");
  if (!asset) root.Fail("no \"asset\" object: not a glTF 2.0 file (glTF 1.0 did not require one)");
  asset->ExpectObject();
  const JsonReader version_reader = asset->Required("version");
  if (version_reader.IsNumber())
    version_reader.Fail("a number, as glTF 1.0 files write it: twinraster reads glTF 2.0 only");
  const std::string version = version_reader.String();
  if (version.substr(0, 2) != "2.") {
    asset->Required("version").Fail("glTF \"" + version + "\": twinraster reads glTF 2.0 only");
  }
  if (auto min_version = asset->Find("minVersion")) {
    const std::string min = min_version->String();
    if (min != "2.0") min_version->Fail("the file needs a glTF reader of version " + min + "; twinraster reads 2.0");
  }
  if (auto required = root.Find("extensionsRequired")) {
    required->ForEachElement([&](const JsonReader& name) {
      const std::string extension = name.String();
      if (!Implemented(extension)) {
        name.Fail("the file requires the extension " + extension + ", which twinraster does not implement");
      }
    });
  }
  if (auto used = root.Find("extensionsUsed")) {
    used->ForEachElement([&](const JsonReader& name) {
      const std::string extension = name.String();
      if (!Implemented(extension)) doc.ignored.push_back("extension " + extension + ": not implemented, not used");
    });
  }
}

// The buffers' bytes: a .glb's BIN chunk for a buffer without a URI, else what the URI names.
void ReadBuffers(const JsonReader& root, const GltfLimits& limits, std::optional<std::vector<std::uint8_t>>& bin,
                 const std::filesystem::path& directory, GltfDocument& doc) {
  const std::optional<JsonReader> buffers = ReadArray(root, "buffers", limits);
  if (!buffers) return;
  std::uint64_t total = 0;
  buffers->ForEachElement([&](const JsonReader& b) {
    b.ExpectObject();
    const auto length = static_cast<std::uint64_t>(b.Required("byteLength").Integer(1, std::int64_t{1} << 53));
    if (!gltf::AddChecked(total, length, total) || total > limits.buffer_bytes) {
      b.Required("byteLength")
          .Fail("the buffers exceed " + std::to_string(limits.buffer_bytes >> 20) + " MiB: refused");
    }
    std::vector<std::uint8_t> bytes;
    if (auto uri = b.Find("uri")) {
      bytes = ReadGltfUri(uri->String(), directory, limits.buffer_bytes, doc.file, uri->path());
    } else {
      if (!bin) b.Fail("a buffer without a \"uri\" must be a .glb's BIN chunk, and the file has none");
      bytes = std::move(*bin);
      bin.reset();
    }
    // A .glb's chunk may carry up to 3 bytes of padding; fewer bytes than declared is an error.
    if (bytes.size() < length) {
      b.Required("byteLength")
          .Fail("says " + std::to_string(length) + " bytes, but the data has " + std::to_string(bytes.size()));
    }
    bytes.resize(static_cast<std::size_t>(length));
    doc.buffers.push_back(std::move(bytes));
  });
}

struct BufferView {
  std::size_t buffer = 0;
  std::uint64_t offset = 0, length = 0;
  std::optional<std::uint64_t> stride;
};

std::vector<BufferView> ReadBufferViews(const JsonReader& root, const GltfLimits& limits, const GltfDocument& doc) {
  std::vector<BufferView> views;
  const std::optional<JsonReader> array = ReadArray(root, "bufferViews", limits);
  if (!array) return views;
  array->ForEachElement([&](const JsonReader& v) {
    v.ExpectObject();
    BufferView view;
    view.buffer = ReadIndex(v.Required("buffer"), doc.buffers.size(), "buffers");
    if (auto offset = v.Find("byteOffset"))
      view.offset = static_cast<std::uint64_t>(offset->Integer(0, std::int64_t{1} << 53));
    view.length = static_cast<std::uint64_t>(v.Required("byteLength").Integer(1, std::int64_t{1} << 53));
    if (auto stride = v.Find("byteStride")) view.stride = static_cast<std::uint64_t>(stride->Integer(4, 252));
    std::uint64_t end = 0;
    if (!gltf::AddChecked(view.offset, view.length, end) || end > doc.buffers[view.buffer].size()) {
      v.Fail("bytes " + std::to_string(view.offset) + " + " + std::to_string(view.length) +
             " lie past the end of buffer " + std::to_string(view.buffer) + " (" +
             std::to_string(doc.buffers[view.buffer].size()) + " bytes)");
    }
    views.push_back(view);
  });
  return views;
}

std::uint32_t ComponentBytes(GltfComponent c) {
  switch (c) {
    case GltfComponent::kByte:
    case GltfComponent::kUnsignedByte: return 1;
    case GltfComponent::kShort:
    case GltfComponent::kUnsignedShort: return 2;
    case GltfComponent::kUnsignedInt:
    case GltfComponent::kFloat: return 4;
  }
  return 4;
}

GltfComponent ReadComponent(const JsonReader& r) {
  const auto value = static_cast<std::uint32_t>(r.Integer(5120, 5126));
  if (value == 5124) r.Fail("5124 (a 32-bit signed integer) is not a glTF 2.0 component type");
  return static_cast<GltfComponent>(value);
}

// The element's components and its size in bytes: matrices of 1- and 2-byte components pad each
// column to 4 bytes, as the spec lays them out.
void ReadType(const JsonReader& r, GltfAccessor& a) {
  static constexpr std::pair<std::string_view, std::uint32_t> kTypes[] = {
      {"SCALAR", 1}, {"VEC2", 2}, {"VEC3", 3}, {"VEC4", 4}, {"MAT2", 4}, {"MAT3", 9}, {"MAT4", 16}};
  a.type = r.String();
  const auto* found =
      std::find_if(std::begin(kTypes), std::end(kTypes), [&](const auto& t) { return t.first == a.type; });
  if (found == std::end(kTypes)) r.Fail("unknown accessor type \"" + a.type + "\"");
  a.components = found->second;
  const std::uint32_t size = ComponentBytes(a.component);
  const std::uint32_t rows = a.type == "MAT2" ? 2 : a.type == "MAT3" ? 3 : 0;
  a.element_bytes = rows == 0 ? std::uint64_t{a.components} * size : rows * ((rows * size + 3) / 4 * 4);
}

// An accessor without a bufferView is all zeros: its elements cost memory the file does not
// pay for, so they are counted against a bound of their own.
constexpr std::uint64_t kMaxZeroElements = std::uint64_t{1} << 20;

void PlaceAccessor(const JsonReader& r, const std::vector<BufferView>& views, GltfAccessor& a) {
  const std::optional<JsonReader> view_reader = r.Find("bufferView");
  if (!view_reader) {
    if (a.count > kMaxZeroElements) {
      r.Fail("an accessor of zeros (no bufferView) with more than " + std::to_string(kMaxZeroElements) + " elements");
    }
    return;
  }
  const BufferView& view = views[ReadIndex(*view_reader, views.size(), "bufferViews")];
  std::uint64_t offset = 0;
  if (auto o = r.Find("byteOffset")) offset = static_cast<std::uint64_t>(o->Integer(0, std::int64_t{1} << 53));
  a.stride = view.stride.value_or(a.element_bytes);
  if (a.stride < a.element_bytes) {
    r.Fail("elements of " + std::to_string(a.element_bytes) + " bytes in a bufferView of stride " +
           std::to_string(a.stride));
  }
  std::uint64_t span = 0, end = 0;
  const bool fits = gltf::MultiplyChecked(a.count - 1, a.stride, span) && gltf::AddChecked(span, offset, end) &&
                    gltf::AddChecked(end, a.element_bytes, end) && end <= view.length;
  if (!fits) {
    r.Fail(std::to_string(a.count) + " elements of " + std::to_string(a.element_bytes) + " bytes, stride " +
           std::to_string(a.stride) + ", from byte " + std::to_string(offset) + ", run past the bufferView's " +
           std::to_string(view.length) + " bytes");
  }
  a.buffer = view.buffer;
  a.offset = view.offset + offset;
}

void ReadAccessors(const JsonReader& root, const GltfLimits& limits, const std::vector<BufferView>& views,
                   GltfDocument& doc) {
  const std::optional<JsonReader> array = ReadArray(root, "accessors", limits);
  if (!array) return;
  array->ForEachElement([&](const JsonReader& r) {
    r.ExpectObject();
    GltfAccessor a;
    a.component = ReadComponent(r.Required("componentType"));
    if (auto normalized = r.Find("normalized")) a.normalized = normalized->Boolean();
    a.count = static_cast<std::uint64_t>(r.Required("count").Integer(1, std::int64_t{1} << 40));
    ReadType(r.Required("type"), a);
    a.sparse = r.Find("sparse").has_value();
    PlaceAccessor(r, views, a);
    doc.accessors.push_back(a);
  });
}

void NoteUndrawn(const JsonReader& root, GltfDocument& doc) {
  const auto count = [&](std::string_view key) -> std::size_t {
    const std::optional<JsonReader> array = root.Find(key);
    return array && array->IsArray() ? array->ExpectArray() : 0;
  };
  if (const std::size_t n = count("animations")) doc.ignored.push_back(Counted(n, "animation") + ": drawn at rest");
  if (const std::size_t n = count("skins"))
    doc.ignored.push_back(Counted(n, "skin") + ": meshes drawn at rest, unskinned");
  if (const std::size_t n = count("images")) {
    doc.ignored.push_back(Counted(n, "image") + ": textures are not drawn, and no image is decoded");
  }
}

GltfDocument ReadDocument(JsonValue json, std::optional<std::vector<std::uint8_t>> bin, const std::string& file_name,
                          const std::filesystem::path& directory, const GltfLimits& limits) {
  GltfDocument doc;
  doc.file = file_name;
  const JsonReader root(json, doc.file);
  if (!root.IsObject()) root.Fail("a glTF file is a JSON object, found " + root.TypeName());
  ReadAsset(root, doc);
  ReadBuffers(root, limits, bin, directory, doc);
  ReadAccessors(root, limits, ReadBufferViews(root, limits, doc), doc);
  gltf::ReadMaterials(root, limits, doc);
  gltf::ReadMeshes(root, limits, doc);
  gltf::ReadCameras(root, limits, doc);
  gltf::ReadNodesAndScenes(root, limits, doc);
  NoteUndrawn(root, doc);
  return doc;
}

}  // namespace

GltfDocument ParseGltf(const std::vector<std::uint8_t>& bytes, const std::string& file_name,
                       const std::filesystem::path& directory, const GltfLimits& limits) {
  if (bytes.size() > limits.file_bytes) {
    throw SceneError(file_name, "(file)", "larger than " + std::to_string(limits.file_bytes >> 20) + " MiB: refused");
  }
  GltfContainer container = SplitGltfContainer(bytes, file_name);
  // The JSON chunk of a .glb is located in the chunk: line and column count from its start.
  RejectBinaryText(container.json, file_name);
  const JsonText text(container.json);
  const ParsedJson json = ParseJson(text.view(), file_name, JsonStrictness::kGltf);
  return ReadDocument(json.root(), std::move(container.bin), file_name, directory, limits);
}

GltfDocument ReadGltf(const std::filesystem::path& file, const GltfLimits& limits) {
  const std::vector<std::uint8_t> bytes = ReadFileBytes(file, limits.file_bytes, file.string(), "(file)");
  return ParseGltf(bytes, file.string(), file.parent_path().empty() ? "." : file.parent_path(), limits);
}

glm::dmat3 QuaternionRotation(const glm::dvec4& q) {
  const double x = q.x, y = q.y, z = q.z, w = q.w;
  glm::dmat3 r;  // r[column][row]: the rotation of a unit quaternion, right-handed, column vectors
  r[0] = {1 - 2 * (y * y + z * z), 2 * (x * y + z * w), 2 * (x * z - y * w)};
  r[1] = {2 * (x * y - z * w), 1 - 2 * (x * x + z * z), 2 * (y * z + x * w)};
  r[2] = {2 * (x * z + y * w), 2 * (y * z - x * w), 1 - 2 * (x * x + y * y)};
  return r;
}

glm::dmat4 LocalMatrix(const GltfNode& node) {
  if (node.has_matrix) return node.matrix;
  const glm::dmat3 r = QuaternionRotation(node.rotation);
  glm::dmat4 m(1.0);  // T · R · S: the columns of R scaled by S, then the translation
  for (int c = 0; c < 3; ++c) m[c] = glm::dvec4(r[c] * node.scale[c], 0.0);
  m[3] = glm::dvec4(node.translation, 1.0);
  return m;
}

}  // namespace twinraster
