#include "scene/obj_file.hpp"

#include "scene/obj_check.hpp"
#include "scene/scene_error.hpp"

// tinyobjloader::tinyobjloader_double, the library twinraster links, is built with real_t =
// double, so that coordinates reach the chain without a rounding to float; its CMake target
// defines TINYOBJLOADER_USE_DOUBLE, which the header must see to agree with it.
#include <tiny_obj_loader.h>
static_assert(sizeof(tinyobj::real_t) == sizeof(double), "link tinyobjloader::tinyobjloader_double");

#include <cerrno>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <streambuf>

namespace twinraster {

namespace {

// tinyobjloader reads from a stream; this one reads the text already in memory, without a copy.
class TextBuffer : public std::streambuf {
 public:
  explicit TextBuffer(std::string_view text) {
    // Only read from: the get area's pointers are not const, the characters are never written.
    char* begin = const_cast<char*>(text.data());
    setg(begin, begin, begin + text.size());
  }
};

// What the callbacks build, in the order tinyobjloader reads the file.
struct Reading {
  ObjMesh mesh;
  std::map<std::string, std::uint32_t, std::less<>> material_numbers;
  std::uint32_t material = kNoMaterial;
  bool any_normal = false;
  std::size_t faces = 0;
  std::vector<std::uint32_t> corner_vertices, corner_normals;  // one face's, reused
};

Reading& Of(void* user_data) { return *static_cast<Reading*>(user_data); }

void OnVertex(void* user_data, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z, tinyobj::real_t /*w*/) {
  Of(user_data).mesh.vertices.emplace_back(x, y, z);
}

void OnNormal(void* user_data, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
  Of(user_data).mesh.normals.emplace_back(x, y, z);
}

// An OBJ index (from 1, or back from -1 over the `count` written so far; 0 for none, in the
// callback API) as an index into the array. CheckObjText has refused 0 and every index out of range.
std::uint32_t Resolve(int index, std::size_t count) {
  const long long resolved = index > 0 ? index - 1LL : static_cast<long long>(count) + index;
  return static_cast<std::uint32_t>(resolved);
}

void OnFace(void* user_data, tinyobj::index_t* indices, int count) {
  Reading& r = Of(user_data);
  ++r.faces;
  r.corner_vertices.clear();
  r.corner_normals.clear();
  for (int k = 0; k < count; ++k) {
    r.corner_vertices.push_back(Resolve(indices[k].vertex_index, r.mesh.vertices.size()));
    const bool has_normal = indices[k].normal_index != 0;
    r.any_normal = r.any_normal || has_normal;
    r.corner_normals.push_back(has_normal ? Resolve(indices[k].normal_index, r.mesh.normals.size()) : kNoNormal);
  }
  // A fan in file order: (0, 1, 2), (0, 2, 3), ... tinyobjloader's own triangulation splits a quad
  // along its shorter diagonal and other polygons by ear clipping, so it is not asked to.
  for (std::size_t k = 1; k + 1 < r.corner_vertices.size(); ++k) {
    r.mesh.triangles.push_back({r.corner_vertices[0], r.corner_vertices[k], r.corner_vertices[k + 1]});
    r.mesh.triangle_normals.push_back({r.corner_normals[0], r.corner_normals[k], r.corner_normals[k + 1]});
    r.mesh.triangle_materials.push_back(r.material);
  }
}

void OnUseMaterial(void* user_data, const char* name, int /*material_id: no .mtl is read*/) {
  Reading& r = Of(user_data);
  // The callback passes the rest of the line as it is.
  std::string_view trimmed(name);
  const std::size_t first = trimmed.find_first_not_of(" \t");
  trimmed = first == std::string_view::npos ? std::string_view()
                                            : trimmed.substr(first, trimmed.find_last_not_of(" \t") - first + 1);
  if (trimmed.empty()) {
    r.material = kNoMaterial;
    return;
  }
  const auto [it, added] =
      r.material_numbers.try_emplace(std::string(trimmed), static_cast<std::uint32_t>(r.mesh.materials.size()));
  if (added) r.mesh.materials.emplace_back(trimmed);
  r.material = it->second;
}

[[noreturn]] void Disagree(const std::string& file_name, const std::string& what) {
  throw std::logic_error(file_name + ": the OBJ check and tinyobjloader disagree on " + what);
}

}  // namespace

std::optional<std::string> ObjFileProblem(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec)) return "is a directory, not an OBJ file";
  if (!std::filesystem::exists(file, ec)) return "no such file";
  if (!std::filesystem::is_regular_file(file, ec)) return "not a regular file";
  return std::nullopt;
}

ObjMesh ReadObjFile(const std::filesystem::path& file) {
  const std::string name = file.string();
  if (const std::optional<std::string> problem = ObjFileProblem(file)) throw SceneError(name, "(file)", *problem);
  std::error_code ec;
  const std::uintmax_t size = std::filesystem::file_size(file, ec);
  if (ec) throw SceneError(name, "(file)", "cannot read the file: " + ec.message());
  if (size > kMaxObjBytes) throw SceneError(name, "(file)", "larger than 256 MiB: not an OBJ file twinraster reads");
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(name, "(file)", std::string("cannot open the file: ") + std::strerror(errno));
  // The size asked above bounds the read, even if the file grows meanwhile.
  std::string text(static_cast<std::size_t>(size), '\0');
  in.read(text.data(), static_cast<std::streamsize>(text.size()));
  if (in.bad()) throw SceneError(name, "(file)", "cannot read the file");
  text.resize(static_cast<std::size_t>(in.gcount()));
  return ParseObj(text, name);
}

ObjMesh ParseObj(std::string_view text, const std::string& file_name) {
  const ObjCounts counts = CheckObjText(text, file_name);

  Reading reading;
  reading.mesh.vertices.reserve(counts.vertices);
  reading.mesh.normals.reserve(counts.normals);
  tinyobj::callback_t callbacks;
  callbacks.vertex_cb = OnVertex;
  callbacks.normal_cb = OnNormal;
  callbacks.index_cb = OnFace;
  callbacks.usemtl_cb = OnUseMaterial;
  TextBuffer buffer(text);
  std::istream stream(&buffer);
  std::string warnings, errors;
  // No MaterialReader: colours come from the scene, and a mesh never makes twinraster open
  // another file (mtllib is skipped).
  const bool read = tinyobj::LoadObjWithCallback(stream, callbacks, &reading, nullptr, &warnings, &errors);
  if (!read || !errors.empty()) {
    throw SceneError(file_name, "(file)", "tinyobjloader: " + errors.substr(0, errors.find('\n')));
  }

  ObjMesh& mesh = reading.mesh;
  if (mesh.vertices.size() != counts.vertices) Disagree(file_name, "the number of vertices");
  if (mesh.normals.size() != counts.normals) Disagree(file_name, "the number of normals");
  if (reading.faces != counts.faces) Disagree(file_name, "the number of faces");
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    for (std::size_t k = 0; k < 3; ++k) {
      const std::uint32_t n = mesh.triangle_normals[t][k];
      if (mesh.triangles[t][k] >= mesh.vertices.size() || (n != kNoNormal && n >= mesh.normals.size())) {
        Disagree(file_name, "an index");
      }
    }
  }
  if (!reading.any_normal) mesh.triangle_normals = {};
  return std::move(reading.mesh);
}

Model ObjModel(ObjMesh mesh, std::string name, Rgb8 colour,
               const std::map<std::string, Rgb8, std::less<>>& material_colours) {
  std::vector<Rgb8> colours;  // by material number
  for (const std::string& material : mesh.materials) {
    const auto it = material_colours.find(material);
    colours.push_back(it == material_colours.end() ? colour : it->second);
  }
  Model model;
  model.name = std::move(name);
  model.vertices = std::move(mesh.vertices);
  model.normals = std::move(mesh.normals);
  model.triangles.reserve(mesh.triangles.size());
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    const std::uint32_t material = mesh.triangle_materials[t];
    model.triangles.push_back(Triangle{mesh.triangles[t], material == kNoMaterial ? colour : colours[material]});
  }
  model.triangle_normals = std::move(mesh.triangle_normals);
  return model;
}

}  // namespace twinraster
