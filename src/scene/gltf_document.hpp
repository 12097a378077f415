// A glTF 2.0 file (.gltf with its .bin files and data: URIs, or .glb) read into typed, checked
// data: every index between objects points at an existing object, every accessor's bytes lie
// inside its buffer, and the node graph is a forest. It keeps only what twinraster draws (meshes,
// nodes, cameras, base colours), names what it leaves out (GltfDocument::ignored), and decodes no
// image. It does not build a Scene: gltf_scene.hpp does.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace twinraster {

// Bounds on what one file may ask for, so that a hostile file costs memory in proportion to its
// size and finite time. Far beyond the assets engines ship.
struct GltfLimits {
  std::uint64_t file_bytes = std::uint64_t{256} << 20;  // the .gltf or .glb itself
  std::uint64_t buffer_bytes = std::uint64_t{1} << 30;  // all buffers together
  std::size_t objects = std::size_t{1} << 20;           // entries of any one top-level array
  // Nodes and primitives cost hundreds of bytes each once read, placed and walked, from as few as
  // 3 bytes of JSON ("{},"), so they have their own limit, checked before any is read: 6.5x the
  // 10,000 nodes and 10,000 primitives of Khronos's NodePerformanceTest, the sample asset made to
  // stress loaders with them (docs/scene-format.md, "A file is untrusted").
  std::size_t nodes = std::size_t{1} << 16;
  std::size_t primitives = std::size_t{1} << 16;           // over all meshes
  std::size_t node_depth = 256;                            // root to deepest node
  std::uint64_t drawn_triangles = std::uint64_t{1} << 26;  // over every instance of every mesh
};

// An accessor's element, as glTF types it.
enum class GltfComponent : std::uint32_t {
  kByte = 5120,
  kUnsignedByte = 5121,
  kShort = 5122,
  kUnsignedShort = 5123,
  kUnsignedInt = 5125,
  kFloat = 5126,
};

struct GltfAccessor {
  GltfComponent component = GltfComponent::kFloat;
  bool normalized = false;
  std::uint32_t components = 1;  // SCALAR 1, VEC2 2, VEC3 3, VEC4 4, MAT2 4, MAT3 9, MAT4 16
  std::string type;              // "SCALAR", "VEC3", ... as written
  std::uint64_t count = 0;
  bool sparse = false;
  // Where element i starts: buffers[*buffer][offset + i * stride], for element_bytes bytes; all of
  // them checked to lie inside that buffer. Without a bufferView the elements are zeros (no buffer).
  std::optional<std::size_t> buffer;
  std::uint64_t offset = 0, stride = 0, element_bytes = 0;
};

// The primitive modes of glTF 2.0, numbered as the file writes them.
enum class GltfMode : std::uint32_t {
  kPoints = 0,
  kLines = 1,
  kLineLoop = 2,
  kLineStrip = 3,
  kTriangles = 4,
  kTriangleStrip = 5,
  kTriangleFan = 6,
};

struct GltfPrimitive {
  GltfMode mode = GltfMode::kTriangles;
  std::size_t position = 0;  // accessor indices
  std::optional<std::size_t> normal, colour, indices, material;
  bool morph_targets = false;
  bool skinned = false;   // JOINTS_0 / WEIGHTS_0
  bool textured = false;  // TEXCOORD_n
};

struct GltfMesh {
  std::string name;
  std::vector<GltfPrimitive> primitives;
};

struct GltfMaterial {
  std::string name;
  glm::dvec4 base_colour{1, 1, 1, 1};  // pbrMetallicRoughness.baseColorFactor, linear
  bool unlit = false;                  // KHR_materials_unlit
  bool textured = false;               // some texture is named: not drawn
  bool double_sided = false;           // "doubleSided": engines cull back faces unless it is true
};

struct GltfCamera {
  std::string name;
  bool orthographic = false;
  // Perspective: yfov (radians), aspect_ratio (absent: the canvas's), znear, zfar (absent: infinite).
  double yfov = 0;
  std::optional<double> aspect_ratio;
  // Orthographic: half the view's width and height.
  double xmag = 0, ymag = 0;
  double znear = 0;
  std::optional<double> zfar;
};

// A node's local transform as written: a matrix, or translation, rotation (a unit quaternion,
// x y z w) and scale, composed T · R · S.
struct GltfNode {
  std::string name;
  bool has_matrix = false;
  glm::dmat4 matrix{1.0};  // column-major, as glTF writes it
  glm::dvec3 translation{0, 0, 0};
  glm::dvec4 rotation{0, 0, 0, 1};
  glm::dvec3 scale{1, 1, 1};
  std::optional<std::size_t> mesh, camera;
  std::vector<std::size_t> children;
  std::optional<std::size_t> parent;  // the node whose children list this one (at most one)
  bool skinned = false;
};

struct GltfSceneRoots {
  std::string name;
  std::vector<std::size_t> nodes;  // roots: no parent
};

struct GltfDocument {
  std::string file;  // as named in every error
  std::vector<std::vector<std::uint8_t>> buffers;
  std::vector<GltfAccessor> accessors;
  std::vector<GltfMesh> meshes;
  std::vector<GltfMaterial> materials;
  std::vector<GltfCamera> cameras;
  std::vector<GltfNode> nodes;
  std::vector<GltfSceneRoots> scenes;
  std::optional<std::size_t> default_scene;  // "scene"
  // What the file holds that is not drawn, one line each ("textures: not drawn; ..."), in order.
  std::vector<std::string> ignored;
};

// Reads and checks a .gltf or .glb file (by its first bytes, not its name). Relative URIs are
// read from the file's folder and may not leave it. Throws SceneError naming the file, where in
// it (a JSON path, or a byte offset in a .glb) and the problem.
GltfDocument ReadGltf(const std::filesystem::path& file, const GltfLimits& limits = {});

// The same from bytes in memory; `directory` is where relative URIs are read (empty: none may be
// read). For the fuzzer and the tests.
GltfDocument ParseGltf(const std::vector<std::uint8_t>& bytes, const std::string& file_name,
                       const std::filesystem::path& directory, const GltfLimits& limits = {});

// The rotation matrix of a unit quaternion (x, y, z, w), in glTF's right-handed frame.
glm::dmat3 QuaternionRotation(const glm::dvec4& q);

// T · R · S, or the matrix: the node's local matrix, in double.
glm::dmat4 LocalMatrix(const GltfNode& node);

}  // namespace twinraster
