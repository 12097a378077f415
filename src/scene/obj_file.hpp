// Reads a Wavefront OBJ file's mesh (v, vn, f and usemtl) into triangles, or one SceneError naming
// the file, the line and the problem.
#pragma once

#include "scene/scene.hpp"

#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster {

// A triangle written before any usemtl (or after a usemtl with no name).
inline constexpr std::uint32_t kNoMaterial = 0xffffffffu;

// The largest OBJ file read, as for a scene file: far beyond any mesh a scene draws on two cores,
// and it keeps /dev/zero-like inputs from eating memory.
inline constexpr std::uintmax_t kMaxObjBytes = std::uintmax_t{256} << 20;

// The light gray an OBJ model's triangles take when the scene gives it no "colour": bright enough
// that shading shows against a dark background, and not white, so that the model still shows on
// the default white one.
inline constexpr Rgb8 kDefaultObjColour{200, 200, 200};

struct ObjMesh {
  std::vector<glm::dvec3> vertices;  // v, in file order (w and vertex colours are not kept)
  std::vector<glm::dvec3> normals;   // vn, in file order, as written (not normalised)
  // Every face as a fan in file order: corners (0, 1, 2), (0, 2, 3), ... (0, n-2, n-1).
  std::vector<std::array<std::uint32_t, 3>> triangles;
  // The vn each triangle corner names, kNoNormal where it names none; empty when no corner of the
  // file names one.
  std::vector<std::array<std::uint32_t, 3>> triangle_normals;
  std::vector<std::uint32_t> triangle_materials;  // index into `materials`, or kNoMaterial
  std::vector<std::string> materials;             // the usemtl names, in order of first use
};

// Why `file` cannot be read as an OBJ file ("no such file", "is a directory, not an OBJ file",
// "not a regular file"), or nullopt.
std::optional<std::string> ObjFileProblem(const std::filesystem::path& file);

// Reads the file (at most kMaxObjBytes); errors name it as `file.string()`.
ObjMesh ReadObjFile(const std::filesystem::path& file);

// The same for text already read; `file_name` is only used in error messages.
ObjMesh ParseObj(std::string_view text, const std::string& file_name);

// The mesh as a scene model (shading kUnlit; the loader decides): each triangle in its
// material's colour from `material_colours`, or in `colour` if it has no material or its
// material no entry there.
Model ObjModel(ObjMesh mesh, std::string name, Rgb8 colour,
               const std::map<std::string, Rgb8, std::less<>>& material_colours = {});

}  // namespace twinraster
