#include "scene/model_reader.hpp"

#include "base/counted.hpp"
#include "scene/gltf_container.hpp"
#include "scene/gltf_document.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/obj_file.hpp"

#include <algorithm>
#include <map>
#include <string>
#include <utility>

namespace twinraster {

namespace {

const std::map<std::string, Rgb8, std::less<>>& NamedColours() {
  // The chapter's six cube colours, plus the neutral ones a scene's background needs.
  static const std::map<std::string, Rgb8, std::less<>> colours = {
      {"red", {255, 0, 0}},       {"green", {0, 255, 0}},    {"blue", {0, 0, 255}},
      {"yellow", {255, 255, 0}},  {"purple", {255, 0, 255}}, {"cyan", {0, 255, 255}},
      {"white", {255, 255, 255}}, {"black", {0, 0, 0}},      {"gray", {128, 128, 128}},
  };
  return colours;
}

constexpr std::pair<const char*, Shading> kShadings[] = {
    {"unlit", Shading::kUnlit}, {"flat", Shading::kFlat}, {"gouraud", Shading::kGouraud}};

Shading ReadShading(const JsonReader& r, bool lit) {
  const std::string name = r.String();
  const auto* found =
      std::find_if(std::begin(kShadings), std::end(kShadings), [&](const auto& s) { return name == s.first; });
  if (found == std::end(kShadings)) {
    const std::string suggestion = ClosestMatch(name, {"unlit", "flat", "gouraud"});
    r.Fail("expected \"unlit\", \"flat\" or \"gouraud\", found \"" + name + "\"" +
           (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)"));
  }
  if (!lit && found->second != Shading::kUnlit) {
    r.Fail("\"" + name + "\" shading needs the scene's \"lighting\"; without it every model is unlit");
  }
  return found->second;
}

// "vertex_colours": one colour per vertex, in the vertices' order; empty when absent.
std::vector<Rgb8> ReadVertexColours(const JsonReader& model, std::size_t vertex_count) {
  const std::optional<JsonReader> r = model.Find("vertex_colours");
  if (!r) return {};
  if (!r->IsArray()) r->Fail("expected a list of colours, one per vertex, found " + r->TypeName());
  const std::size_t count = r->ExpectArray();
  if (count != vertex_count) {
    r->Fail(Counted(count, "colour") + " for " + Counted(vertex_count, "vertex", "vertices") +
            ": give one colour per vertex");
  }
  std::vector<Rgb8> colours;
  colours.reserve(count);
  r->ForEachElement([&](const JsonReader& c) { colours.push_back(ReadColour(c)); });
  return colours;
}

// [v0, v1, v2, colour]; with vertex colours the colour may be left out, and is then v0's (the
// provoking vertex's), which only a wireframe or the book's rules draw.
Triangle ReadTriangle(const JsonReader& t, std::size_t vertex_count, const std::vector<Rgb8>& vertex_colours) {
  const bool colour_optional = !vertex_colours.empty();
  if (!t.IsArray()) {
    t.Fail(colour_optional ? "expected [v0, v1, v2] or [v0, v1, v2, colour], found " + t.TypeName()
                           : "expected [v0, v1, v2, colour], found " + t.TypeName());
  }
  const std::size_t size = t.ExpectArray();
  if (colour_optional && size != 3 && size != 4) {
    t.Fail("expected an array of 3 or 4 elements, found " + std::to_string(size));
  } else if (!colour_optional && size == 3) {
    t.Fail("expected [v0, v1, v2, colour]: a triangle without a colour needs the model's \"vertex_colours\"");
  } else if (!colour_optional) {
    t.ExpectArray(4);
  }
  Triangle triangle;
  for (std::size_t k = 0; k < 3; ++k) {
    const JsonReader index = t[k];
    if (vertex_count == 0) index.Fail("the model has no vertices");
    triangle.v[k] = static_cast<std::uint32_t>(index.Integer(0, static_cast<std::int64_t>(vertex_count) - 1));
  }
  triangle.colour = size == 4 ? ReadColour(t[3]) : vertex_colours[triangle.v[0]];
  return triangle;
}

Model ReadVertexModel(const JsonReader& r, const std::string& name) {
  Model model;
  model.name = name;
  const JsonReader vertices = r.Required("vertices");
  const std::size_t vertex_count = vertices.ExpectArray();
  model.vertices.reserve(vertex_count);
  vertices.ForEachElement([&](const JsonReader& v) { model.vertices.push_back(v.Vec3()); });
  model.vertex_colours = ReadVertexColours(r, vertex_count);

  const JsonReader triangles = r.Required("triangles");
  model.triangles.reserve(triangles.ExpectArray());
  triangles.ForEachElement(
      [&](const JsonReader& t) { model.triangles.push_back(ReadTriangle(t, vertex_count, model.vertex_colours)); });
  return model;
}

// "materials": {"name": colour, ...}; every name must be one the file uses (usemtl), so that a
// misspelt one is caught instead of silently leaving its triangles in the model's colour.
std::map<std::string, Rgb8, std::less<>> ReadMaterials(const JsonReader& r, const std::vector<std::string>& used) {
  std::map<std::string, Rgb8, std::less<>> colours;
  for (const std::string_view name : r.Keys()) {
    const JsonReader entry = *r.Find(name);
    if (std::find(used.begin(), used.end(), name) == used.end()) {
      std::string problem = "the OBJ file never uses material \"" + std::string(name) + "\"";
      if (used.empty()) {
        problem += ": it has no usemtl lines";
      } else {
        const std::string suggestion = ClosestMatch(name, used);
        if (!suggestion.empty()) problem += " (did you mean \"" + suggestion + "\"?)";
        std::string list;
        for (const std::string& u : used) list += (list.empty() ? "" : ", ") + u;
        problem += "; it uses " + list;
      }
      entry.Fail(problem);
    }
    colours.emplace(name, ReadColour(entry));
  }
  return colours;
}

// A model's "obj" or "gltf" written as a data: URI: its bytes, refused unless its media type is
// one of `media_types`. Problems in the bytes are then named as "FILE (PATH, a data: URI)".
std::vector<std::uint8_t> ReadDataUri(const JsonReader& r, const std::string& written, std::uint64_t max_bytes,
                                      std::initializer_list<std::string_view> media_types) {
  DataUri uri = DecodeDataUri(written, max_bytes, r.file(), r.path());
  if (std::find(media_types.begin(), media_types.end(), uri.media_type) == media_types.end()) {
    std::string valid;
    for (const std::string_view type : media_types) {
      if (!type.empty()) valid += std::string(valid.empty() ? "" : ", ") + std::string(type);
    }
    r.Fail("a data: URI of media type \"" + uri.media_type + "\"; use one of " + valid + " (or none)");
  }
  return std::move(uri.bytes);
}

std::string DataUriName(const JsonReader& r) { return r.file() + " (" + r.path() + ", a data: URI)"; }

// What a model's source says of a data: URI: not the whole of it.
std::string DataUriSource(const std::string& written) {
  return written.substr(0, written.find(',')) + " (" + Counted(written.size(), "character") + ")";
}

ObjMesh ReadObjMesh(const JsonReader& obj, const std::string& written, const std::filesystem::path& directory) {
  if (IsDataUri(written)) {
    const std::vector<std::uint8_t> bytes =
        ReadDataUri(obj, written, kMaxObjBytes, {"", "text/plain", "model/obj", "application/octet-stream"});
    return ParseObj(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()), DataUriName(obj));
  }
  const std::filesystem::path file = directory / std::filesystem::path(written);
  // Named as the scene wrote it, and where that led from the scene's directory.
  if (const std::optional<std::string> problem = ObjFileProblem(file)) {
    const std::string looked = file.string() == written ? "" : " (looked for " + file.string() + ")";
    obj.Fail("OBJ file \"" + written + "\"" + looked + ": " + *problem);
  }
  return ReadObjFile(file);  // its errors name the file as opened, and the line
}

Model ReadObjModel(const JsonReader& r, const std::string& name, const std::filesystem::path& directory) {
  const JsonReader obj = r.Required("obj");
  const std::string written = obj.String();
  if (written.empty()) obj.Fail("expected the path of an OBJ file, found \"\"");
  ObjMesh mesh = ReadObjMesh(obj, written, directory);
  const std::optional<JsonReader> colour_reader = r.Find("colour");
  const Rgb8 colour = colour_reader ? ReadColour(*colour_reader) : kDefaultObjColour;
  std::map<std::string, Rgb8, std::less<>> material_colours;
  if (const std::optional<JsonReader> materials = r.Find("materials"))
    material_colours = ReadMaterials(*materials, mesh.materials);
  Model model = ObjModel(std::move(mesh), name, colour, material_colours);
  model.vertex_colours = ReadVertexColours(r, model.vertices.size());
  model.source = IsDataUri(written) ? DataUriSource(written) : written;
  return model;
}

}  // namespace

Rgb8 ReadColour(const JsonReader& r) {
  if (r.IsString()) {
    const std::string name = r.LowercaseString();
    const auto it = NamedColours().find(name);
    if (it != NamedColours().end()) return it->second;
    std::vector<std::string> names;
    std::string list;
    for (const auto& entry : NamedColours()) {
      names.push_back(entry.first);
      list += (list.empty() ? "" : ", ") + entry.first;
    }
    const std::string suggestion = ClosestMatch(name, names);
    r.Fail("unknown colour \"" + r.String() + "\"" +
           (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)") + "; use one of " + list +
           " (in any case), or [r, g, b] with 0..255");
  }
  if (!r.IsArray()) r.Fail("expected a colour name or [r, g, b], found " + r.TypeName());
  r.ExpectArray(3);
  const auto channel = [&](std::size_t i) { return static_cast<std::uint8_t>(r[i].Integer(0, 255)); };
  return Rgb8{channel(0), channel(1), channel(2)};
}

const char* ShadingName(Shading shading) {
  for (const auto& [name, s] : kShadings) {
    if (s == shading) return name;
  }
  return "?";
}

// "gltf": a glTF file's default scene as one model, each node's meshes moved by its chain.
Model ReadGltfModel(const JsonReader& r, const std::string& name, const std::filesystem::path& directory, bool lit) {
  for (const char* key : {"vertices", "triangles", "obj", "colour", "materials"}) {
    if (auto found = r.Find(key))
      found->Fail("a model read from \"gltf\" takes its geometry and colours from the file");
  }
  const JsonReader gltf = r.Required("gltf");
  const std::string written = gltf.String();
  if (written.empty()) gltf.Fail("expected the path of a .gltf or .glb file, found \"\"");
  if (IsDataUri(written)) {
    const GltfLimits limits;
    const std::vector<std::uint8_t> bytes =
        ReadDataUri(gltf, written, limits.file_bytes,
                    {"", "model/gltf+json", "model/gltf-binary", "application/json", "application/octet-stream"});
    // No directory: a glTF file carried inline reads no file either (its buffers are data: URIs).
    Model model = GltfModel(ParseGltf(bytes, DataUriName(gltf), {}, limits), name, lit);
    model.source = DataUriSource(written);
    return model;
  }
  const std::filesystem::path file = directory / std::filesystem::path(written);
  Model model = GltfModel(ReadGltf(file), name, lit);  // its errors name the file as opened
  model.source = written;
  return model;
}

Model ReadModel(const JsonReader& r, const std::string& name, const std::filesystem::path& directory, bool lit) {
  r.ExpectObject({"vertices", "triangles", "obj", "gltf", "colour", "materials", "shading", "vertex_colours"});
  if (r.Find("gltf")) {
    if (auto colours = r.Find("vertex_colours"))
      colours->Fail("a model read from \"gltf\" takes its colours from the file");
    const std::optional<JsonReader> shading = r.Find("shading");
    const std::optional<Shading> asked = shading ? std::optional(ReadShading(*shading, lit)) : std::nullopt;
    Model model = ReadGltfModel(r, name, directory, lit);
    if (asked) model.shading = *asked;
    return model;
  }
  const std::optional<JsonReader> obj = r.Find("obj");
  if (!obj) {
    for (const char* key : {"colour", "materials"}) {
      if (auto found = r.Find(key)) {
        found->Fail(
            "only for a model read from an OBJ file (\"obj\"); a model written as \"vertices\" gives each "
            "triangle its colour");
      }
    }
  } else {
    for (const char* key : {"vertices", "triangles"}) {
      if (auto found = r.Find(key))
        found->Fail("a model is read from \"obj\" or written as \"vertices\" and \"triangles\", not both");
    }
  }
  // Checked before an OBJ file is read: a mistake here costs nothing.
  const std::optional<JsonReader> shading = r.Find("shading");
  const std::optional<Shading> asked = shading ? std::optional(ReadShading(*shading, lit)) : std::nullopt;

  Model model = obj ? ReadObjModel(r, name, directory) : ReadVertexModel(r, name);
  const bool has_normals = !model.triangle_normals.empty();
  model.shading = asked.value_or(!lit ? Shading::kUnlit : has_normals ? Shading::kGouraud : Shading::kFlat);
  return model;
}

}  // namespace twinraster
