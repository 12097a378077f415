// The scene as the chapter describes it: models, instances with transforms, a camera, the
// viewport and canvas; plain data, already validated by the loader.
#pragma once

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace twinraster {

struct Rgb8 {
  std::uint8_t r = 0, g = 0, b = 0;
  friend bool operator==(const Rgb8&, const Rgb8&) = default;
};

// The largest canvas side: lavapipe's maxImageDimension2D and maxViewportDimensions (both 16384).
inline constexpr std::uint32_t kMaxCanvasSize = 16384;

// The canvas is the image we draw into: Cw x Ch pixels.
struct Canvas {
  std::uint32_t width = 0;   // Cw
  std::uint32_t height = 0;  // Ch
  Rgb8 background{255, 255, 255};
};

// The viewport is the window into the world: Vw x Vh at distance d from the camera.
// How camera space reaches the viewport: the chapter's perspective (x·d/z, y·d/z), or
// orthographic (x, y whatever z; Catlike's section 5.1), where d plays no part.
enum class Projection { kPerspective, kOrthographic };

struct Viewport {
  double width = 1;     // Vw
  double height = 1;    // Vh
  double distance = 1;  // d (Catlike's focal length)
  Projection projection = Projection::kPerspective;
};

// The chapter keeps no depth; Vulkan needs it. Camera-space z in [near, far] maps to depth [0, 1]
// (depth test LESS, cleared to 1), or with reversed Z to [1, 0] (test GREATER, cleared to 0), which
// spends float precision where perspective squeezes distant depths together.
struct Depth {
  double near = 0.1;
  double far = 100;
  bool reversed = false;
};

struct Triangle {
  std::array<std::uint32_t, 3> v{};  // indices into the model's vertices
  // Its flat colour. A model with vertex colours is filled with those instead; this one is then
  // only for wireframe edges and the book's rules (by default its first vertex's colour).
  Rgb8 colour;
};

// How a model's triangles take the scene's light. Unlit: their own flat colours, as without
// lighting (and always when the scene has none), or their vertex colours interpolated. Flat: each
// triangle lit once, with its face normal, at its first vertex (the provoking vertex, whose flat
// outputs Vulkan uses). Gouraud: each vertex lit with its own normal, the colour interpolated
// across the triangle.
enum class Shading { kUnlit, kFlat, kGouraud };

// A triangle corner with no normal in the file (an OBJ face written without vn).
inline constexpr std::uint32_t kNoNormal = 0xffffffffu;

struct Model {
  std::string name;
  std::vector<glm::dvec3> vertices;
  std::vector<Triangle> triangles;
  // An OBJ's vn, and which of them each triangle corner names (kNoNormal where none); both empty
  // for a model written as JSON vertices, and triangle_normals also when no corner names a vn.
  // The chain computes the normals a lit model lacks.
  std::vector<glm::dvec3> normals;
  std::vector<std::array<std::uint32_t, 3>> triangle_normals;
  Shading shading = Shading::kUnlit;
  // Empty, or one 8-bit sRGB-encoded colour per vertex (glTF's COLOR_0): when present, a filled
  // triangle takes each corner's colour (its base colour, when lit) instead of its own, and
  // interpolates it as Gouraud colours are (docs/scene-format.md).
  std::vector<Rgb8> vertex_colours;
  std::string source;  // the OBJ file as the scene wrote it, or empty
};

// One step of a transform written as a list, in the order written:
// "transform": [{"rotation": {...}}, {"translation": [x, y, z]}, {"scale": s}]; or, for an
// instance of a glTF node, one node's local matrix (kMatrix), from the mesh's node up to its root.
struct TransformStep {
  enum class Kind { kScale, kRotation, kTranslation, kMatrix };
  Kind kind = Kind::kScale;
  glm::dvec3 vector{1, 1, 1};  // the scale factors (kScale) or the offset (kTranslation)
  glm::dmat3 rotation{1.0};    // kRotation, in the chapter's convention
  glm::dmat4 matrix{1.0};      // kMatrix: an affine matrix (last row 0 0 0 1), column-major
  std::string label;           // kMatrix: whose matrix, e.g. "node 3 \"wheel\" (T·R·S)"
};

// An instance's transform. Written as an object it is applied scale first, then rotation, then
// translation (M_Model = I_T · I_R · I_S, the chapter's order). Written as a list, its steps are
// applied in the order written, and the three fields stay the identity but for a grid's offset
// in translation, which moves the whole result in world space:
// M_Model = I_T · I_R · I_S · step_n · ... · step_1.
struct Transform {
  glm::dvec3 scale{1, 1, 1};
  // A 3x3 matrix in the chapter's convention (see matrices.hpp); the loader composes a list of
  // axis rotations into one matrix.
  glm::dmat3 rotation{1.0};
  // For --rules book only: a rotation written as one {axis, degrees} with the chapter demos' own
  // entries (BookRotation, scene/rotation.hpp); null for any other rotation. Shared by a grid's copies.
  std::shared_ptr<const glm::dmat3> book_rotation;
  glm::dvec3 translation{0, 0, 0};
  // The list form's steps, or null; shared by the copies of a grid.
  std::shared_ptr<const std::vector<TransformStep>> steps;
};

struct Instance {
  std::size_t model = 0;  // index into Scene::models
  Transform transform;
};

// The chapter's answer to "What if we wanted to render one million cubes?" is instances; a grid
// writes many of them at once (Catlike's centred grid). An instance written with
// "grid": {"count": [nx, ny, nz], "spacing": [sx, sy, sz]} stands for nx·ny·nz copies: copy
// (i, j, k) is moved by ((i - (nx-1)/2)·sx, (j - (ny-1)/2)·sy, (k - (nz-1)/2)·sz) in world space
// on top of the instance's own translation, keeping its scale and rotation. The loader writes the
// copies out as Scene::instances [first, first + nx·ny·nz), i fastest, and keeps this record.
struct InstanceGrid {
  std::size_t written = 0;  // the instance's index among the file's "instances"
  std::size_t first = 0;    // its first copy in Scene::instances
  std::array<std::uint32_t, 3> count{1, 1, 1};
  glm::dvec3 spacing{0, 0, 0};
  std::size_t copies() const { return std::size_t{count[0]} * count[1] * count[2]; }
};

// At most this many instances in a scene, grids' copies included: 2^24, far more than a
// 2-core machine draws in a second. At that count the scene's instances take 2 GiB (128 bytes
// each) and the draw list's F another 1 GiB: large, but bounded.
inline constexpr std::size_t kMaxInstances = std::size_t{1} << 24;

// The camera's own transform in the world (C_T, C_R); M_Camera is its inverse.
struct Camera {
  glm::dvec3 position{0, 0, 0};
  glm::dmat3 rotation{1.0};
  std::shared_ptr<const glm::dmat3> book_rotation = nullptr;  // as Transform's
};

// Light in Computer Graphics from Scratch's diffuse model: at a surface point with normal n,
// I = ambient + sum over lights of intensity * max(0, n.l) / (|n| |l|), where l points from the
// surface toward the light; the colour is the base colour times min(I, 1). Lights live in world
// space.
struct Light {
  enum class Kind { kDirectional, kPoint };
  Kind kind = Kind::kDirectional;
  glm::dvec3 vector{0, 0, 1};  // kDirectional: l itself (toward the light); kPoint: its position
  double intensity = 0;
};

struct Lighting {
  double ambient = 0;
  std::vector<Light> lights;
};

struct Scene {
  std::string name;  // the file's stem, for default output names
  Canvas canvas;
  Viewport viewport;
  Depth depth;
  Camera camera;
  std::vector<Model> models;
  std::vector<Instance> instances;  // every copy of every grid written out
  std::vector<InstanceGrid> grids;  // which instances came from a grid, in order
  bool wireframe = false;           // draw triangle edges only, as the chapter's figures do
  // Absent: every model keeps its flat triangle colours, exactly as without this feature.
  std::optional<Lighting> lighting;
  // What the file holds that is not drawn (a glTF file's textures, animations, lines, ...), one
  // line each, for the commands to print: the image is still the file's geometry.
  std::vector<std::string> notes;
};

}  // namespace twinraster
