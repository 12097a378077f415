#include "scene/gltf_scene.hpp"

#include "base/counted.hpp"
#include "scene/framing.hpp"
#include "scene/gltf_build.hpp"
#include "scene/scene_error.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>

namespace twinraster::gltf {

std::vector<PlacedNode> WalkScene(const GltfDocument& doc, const std::optional<std::size_t>& scene) {
  std::vector<std::size_t> roots;
  if (scene) {
    roots = doc.scenes[*scene].nodes;
  } else {
    for (std::size_t i = 0; i < doc.nodes.size(); ++i) {
      if (!doc.nodes[i].parent) roots.push_back(i);
    }
  }
  std::vector<PlacedNode> walk, stack;
  for (auto root = roots.rbegin(); root != roots.rend(); ++root)
    stack.push_back({*root, LocalMatrix(doc.nodes[*root])});
  while (!stack.empty()) {  // the graph is a forest (gltf_document checked), so this ends
    const PlacedNode at = stack.back();
    stack.pop_back();
    walk.push_back(at);
    const std::vector<std::size_t>& children = doc.nodes[at.node].children;
    for (auto child = children.rbegin(); child != children.rend(); ++child) {
      stack.push_back({*child, at.world * LocalMatrix(doc.nodes[*child])});
    }
  }
  return walk;
}

std::shared_ptr<const std::vector<TransformStep>> NodeSteps(const GltfDocument& doc, std::size_t node) {
  auto steps = std::make_shared<std::vector<TransformStep>>();
  for (std::optional<std::size_t> at = node; at; at = doc.nodes[*at].parent) {
    const GltfNode& n = doc.nodes[*at];
    TransformStep step;
    step.kind = TransformStep::Kind::kMatrix;
    step.matrix = LocalMatrix(n);
    step.label = "node " + std::to_string(*at) + (n.name.empty() ? "" : " \"" + n.name + "\"") +
                 (n.has_matrix ? " (matrix)" : " (T·R·S)");
    steps->push_back(std::move(step));
  }
  TransformStep mirror;
  mirror.kind = TransformStep::Kind::kScale;
  mirror.vector = kMirror;
  mirror.label = "the chapter's mirror: glTF's right-handed frame into the left-handed world";
  steps->push_back(std::move(mirror));
  return steps;
}

}  // namespace twinraster::gltf

namespace twinraster {

namespace {

// Bounds what the node chains cost: every instance keeps its chain's steps for explain.
constexpr std::size_t kMaxChainSteps = std::size_t{1} << 18;

std::optional<std::size_t> ChosenScene(const GltfDocument& doc, const SceneChoice& choice) {
  if (choice.scene) {
    if (*choice.scene >= doc.scenes.size()) {
      throw SceneError(doc.file, "scenes",
                       "--scene " + std::to_string(*choice.scene) + ": the file has " +
                           Counted(doc.scenes.size(), "scene") + ValidIndices(doc.scenes.size()));
    }
    return choice.scene;
  }
  if (doc.default_scene) return doc.default_scene;
  if (!doc.scenes.empty()) return 0;
  return std::nullopt;
}

// The models of every primitive of the meshes the walk meets, made once per (mesh, primitive).
class ModelTable {
 public:
  ModelTable(const GltfDocument& doc, Scene& scene) : doc_(doc), scene_(scene) {
    for (const std::vector<std::uint8_t>& b : doc_.buffers) buffer_bytes_ += b.size();
  }

  // The scene's model index, or empty for a primitive that draws nothing.
  std::optional<std::size_t> Model(std::size_t mesh, std::size_t primitive) {
    const auto key = std::make_pair(mesh, primitive);
    if (const auto found = made_.find(key); found != made_.end()) return found->second;
    Charge(mesh, primitive);
    std::optional<twinraster::Model> model = gltf::PrimitiveModel(doc_, mesh, primitive, scene_.notes);
    std::optional<std::size_t> index;
    if (model) {
      index = scene_.models.size();
      scene_.models.push_back(std::move(*model));
    }
    made_.emplace(key, index);
    return index;
  }

 private:
  // Primitives may share accessors, so what the models hold is bounded on its own: elements read
  // (vertices, normals, colours, indices) up to twice the buffers' bytes plus 2^22, which the
  // files that share a vertex buffer between materials stay far below, and a small file that
  // names one large accessor from many primitives does not.
  void Charge(std::size_t mesh, std::size_t primitive) {
    const GltfPrimitive& p = doc_.meshes[mesh].primitives[primitive];
    std::uint64_t elements = doc_.accessors[p.position].count;
    for (const std::optional<std::size_t>& a : {p.normal, p.colour, p.indices})
      elements += a ? doc_.accessors[*a].count : 0;
    read_ += elements;
    if (read_ > 2 * buffer_bytes_ + (std::uint64_t{1} << 22)) {
      throw SceneError(doc_.file, "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]",
                       "the primitives read " + std::to_string(read_) + " accessor elements from " +
                           std::to_string(buffer_bytes_) + " bytes of buffers: out of proportion, refused");
    }
  }

  const GltfDocument& doc_;
  Scene& scene_;
  std::uint64_t buffer_bytes_ = 0;  // every buffer's, summed once
  std::uint64_t read_ = 0;
  std::map<std::pair<std::size_t, std::size_t>, std::optional<std::size_t>> made_;
};

void NoteUndrawn(const GltfDocument& doc, const std::vector<gltf::PlacedNode>& walk, Scene& scene) {
  std::size_t textured = 0, skinned = 0, morphed = 0, single_sided = 0;
  for (const gltf::PlacedNode& at : walk) {
    const GltfNode& node = doc.nodes[at.node];
    if (!node.mesh) continue;
    for (const GltfPrimitive& p : doc.meshes[*node.mesh].primitives) {
      const bool material_textured = p.material && doc.materials[*p.material].textured;
      textured += p.textured || material_textured;
      skinned += p.skinned || node.skinned;
      morphed += p.morph_targets;
      single_sided += !(p.material && doc.materials[*p.material].double_sided);
    }
  }
  if (textured) scene.notes.push_back(Counted(textured, "textured primitive") + ": drawn in their base colour");
  if (skinned) scene.notes.push_back(Counted(skinned, "skinned primitive") + ": drawn at rest, unskinned");
  if (morphed) scene.notes.push_back(Counted(morphed, "primitive") + " with morph targets: drawn without them");
  if (single_sided) {
    scene.notes.push_back(Counted(single_sided, "single-sided primitive") +
                          ": drawn from both sides, as the chapter draws; an engine that "
                          "culls their back faces may leave holes where one shows (docs/verify.md)");
  }
  scene.notes.insert(scene.notes.end(), doc.ignored.begin(), doc.ignored.end());
}

// The node chain and the mirror, as NodeSteps wrote them, composed in double as chain/ composes
// a list (each step applied after the last).
glm::dmat4 ChainMatrix(const std::vector<TransformStep>& steps) {
  glm::dmat4 m(1.0);
  for (const TransformStep& step : steps) {
    glm::dmat4 s(1.0);
    if (step.kind == TransformStep::Kind::kMatrix) s = step.matrix;
    if (step.kind == TransformStep::Kind::kScale)
      s = glm::dmat4(glm::dvec4(step.vector.x, 0, 0, 0), glm::dvec4(0, step.vector.y, 0, 0),
                     glm::dvec4(0, 0, step.vector.z, 0), glm::dvec4(0, 0, 0, 1));
    m = s * m;
  }
  return m;
}

// Whether a lit instance can be drawn: its normals need the inverse transpose of M_Model's 3x3
// (chain/normals.hpp), which a chain with a scale of 0 lacks. A chain that collapses every
// triangle to a line or a point (each 2x2 minor 0, as a node scaled to 0 to hide it is) covers no
// pixel on any device, so it is left out (false). One that only flattens is drawn by engines as
// a plane, but not lit by the chapter's rule: refused, as a scene file's zero scale is.
bool LitChainDrawn(const GltfDocument& doc, std::size_t node, const std::vector<TransformStep>& steps) {
  const glm::dmat3 m(ChainMatrix(steps));
  const double det = glm::determinant(m);
  if (det != 0 && std::isfinite(det)) return true;
  const glm::dvec3 zero(0.0);
  if (glm::cross(m[0], m[1]) == zero && glm::cross(m[1], m[2]) == zero && glm::cross(m[2], m[0]) == zero) return false;
  throw SceneError(doc.file, "nodes[" + std::to_string(node) + "]",
                   "a lit mesh whose node chain has no inverse (a scale of 0 on one axis, or a matrix "
                   "without an inverse or out of double's range), so its normals have no inverse transpose");
}

void AddInstances(const GltfDocument& doc, const std::vector<gltf::PlacedNode>& walk, Scene& scene) {
  ModelTable models(doc, scene);
  std::size_t chain_steps = 0, collapsed = 0;
  std::uint64_t drawn = 0;
  const GltfLimits limits;
  for (const gltf::PlacedNode& at : walk) {
    const std::optional<std::size_t> mesh = doc.nodes[at.node].mesh;
    if (!mesh) continue;
    std::shared_ptr<const std::vector<TransformStep>> steps;
    for (std::size_t p = 0; p < doc.meshes[*mesh].primitives.size(); ++p) {
      const std::optional<std::size_t> model = models.Model(*mesh, p);
      if (!model) continue;
      if (!steps) {
        steps = gltf::NodeSteps(doc, at.node);
        chain_steps += steps->size();
      }
      if (scene.models[*model].shading != Shading::kUnlit && !LitChainDrawn(doc, at.node, *steps)) {
        ++collapsed;
        continue;
      }
      drawn += scene.models[*model].triangles.size();
      if (chain_steps > kMaxChainSteps || drawn > limits.drawn_triangles || scene.instances.size() >= kMaxInstances) {
        throw SceneError(doc.file, "nodes[" + std::to_string(at.node) + "]",
                         "the scene draws more than " + std::to_string(limits.drawn_triangles) +
                             " triangles, or its node chains are too long to keep: refused");
      }
      Instance instance;
      instance.model = *model;
      instance.transform.steps = steps;
      scene.instances.push_back(std::move(instance));
    }
  }
  if (collapsed) {
    scene.notes.push_back(Counted(collapsed, "lit primitive") +
                          " under a node chain scaled to 0: not drawn, as no device would cover a pixel of them");
  }
}

// Every point the instances draw, in glTF's world (the frame before the mirror).
PointWalk WorldPoints(const Scene& scene) {
  return [&scene](const auto& point) {
    for (const Instance& instance : scene.instances) {
      const Model& model = scene.models[instance.model];
      glm::dmat4 world(1.0);  // the node chain without the final mirror
      const std::vector<TransformStep>& steps = *instance.transform.steps;
      for (std::size_t k = 0; k + 1 < steps.size(); ++k) world = steps[k].matrix * world;
      for (const Triangle& t : model.triangles) {
        for (const std::uint32_t v : t.v) point(glm::dvec3(world * glm::dvec4(model.vertices[v], 1.0)));
      }
    }
  };
}

}  // namespace

Scene GltfScene(const GltfDocument& doc, const SceneChoice& choice, const std::string& name) {
  Scene scene;
  scene.name = name;
  const std::optional<std::size_t> chosen = ChosenScene(doc, choice);
  if (!chosen) scene.notes.push_back("no scenes: every root node is drawn");
  const std::vector<gltf::PlacedNode> walk = gltf::WalkScene(doc, chosen);
  AddInstances(doc, walk, scene);
  if (scene.instances.empty()) {
    throw SceneError(doc.file, chosen ? "scenes[" + std::to_string(*chosen) + "]" : "nodes",
                     "nothing to draw: no node of the scene holds a mesh with triangles" +
                         (scene.notes.empty() ? std::string() : " (" + scene.notes.front() + ")"));
  }
  NoteUndrawn(doc, walk, scene);
  if (const std::optional<gltf::PlacedNode> camera = gltf::ChooseCamera(doc, walk, choice.camera)) {
    gltf::PlaceCamera(doc, *camera, choice.size, scene);
  } else {
    FrameAsset(BoundingSphere(WorldPoints(scene)), scene);
    if (choice.size) ResizeCanvas(scene, *choice.size);
  }
  scene.canvas.background = Rgb8{40, 40, 48};
  return scene;
}

Model GltfModel(const GltfDocument& doc, const std::string& name, bool lit) {
  Scene scene = GltfScene(doc, SceneChoice{}, name);
  Model out;
  out.name = name;
  out.source = doc.file;
  bool all_unlit = true, all_normals = true;
  const bool any_colours =
      std::any_of(scene.models.begin(), scene.models.end(), [](const Model& m) { return !m.vertex_colours.empty(); });
  for (const Instance& instance : scene.instances) {
    const Model& model = scene.models[instance.model];
    const glm::dmat4 m = ChainMatrix(*instance.transform.steps);
    const glm::dmat3 n = glm::transpose(glm::inverse(glm::dmat3(m)));
    const auto first = static_cast<std::uint32_t>(out.vertices.size());
    for (const glm::dvec3& v : model.vertices) out.vertices.push_back(glm::dvec3(m * glm::dvec4(v, 1.0)));
    if (any_colours) {  // every vertex a colour: a primitive without COLOR_0 in its material's
      const Rgb8 own = model.triangles.empty() ? Rgb8{} : model.triangles.front().colour;
      if (model.vertex_colours.empty())
        out.vertex_colours.insert(out.vertex_colours.end(), model.vertices.size(), own);
      else
        out.vertex_colours.insert(out.vertex_colours.end(), model.vertex_colours.begin(), model.vertex_colours.end());
    }
    const auto first_normal = static_cast<std::uint32_t>(out.normals.size());
    for (const glm::dvec3& v : model.normals) out.normals.push_back(n * v);
    for (std::size_t t = 0; t < model.triangles.size(); ++t) {
      Triangle triangle = model.triangles[t];
      for (std::uint32_t& v : triangle.v) v += first;
      out.triangles.push_back(triangle);
      std::array<std::uint32_t, 3> corners{kNoNormal, kNoNormal, kNoNormal};
      if (!model.triangle_normals.empty()) {
        for (std::size_t k = 0; k < 3; ++k) corners[k] = model.triangle_normals[t][k] + first_normal;
      }
      out.triangle_normals.push_back(corners);
    }
    all_unlit = all_unlit && model.shading == Shading::kUnlit;
    all_normals = all_normals && !model.triangle_normals.empty();
  }
  out.shading = !lit || all_unlit ? Shading::kUnlit : all_normals ? Shading::kGouraud : Shading::kFlat;
  if (out.shading != Shading::kGouraud) {
    out.normals.clear();
    out.triangle_normals.clear();
  }
  return out;
}

bool IsGltfName(const std::filesystem::path& file) {
  std::string extension = file.extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".gltf" || extension == ".glb";
}

Scene SceneForGltf(const std::filesystem::path& file, const SceneChoice& choice) {
  return GltfScene(ReadGltf(file), choice, file.stem().string());
}

}  // namespace twinraster
