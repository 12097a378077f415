// The glTF reader's nodes and scenes (gltf_parse.hpp): the node graph must be a forest.
#include "scene/gltf_parse.hpp"

#include <glm/geometric.hpp>

#include <cmath>

namespace twinraster::gltf {

namespace {

template <int N>
glm::vec<N, double> ReadVector(const JsonReader& r) {
  r.ExpectArray(N);
  glm::vec<N, double> v(0.0);
  int k = 0;
  r.ForEachElement([&](const JsonReader& c) { v[k++] = c.Number(); });
  return v;
}

glm::dmat4 ReadMatrix(const JsonReader& r) {
  r.ExpectArray(16);
  glm::dmat4 m(0.0);
  int k = 0;
  r.ForEachElement([&](const JsonReader& c) {  // column-major: element k is column k / 4, row k % 4
    m[k / 4][k % 4] = c.Number();
    ++k;
  });
  if (m[0][3] != 0 || m[1][3] != 0 || m[2][3] != 0 || m[3][3] != 1) {
    r.Fail("a node matrix's last row must be 0 0 0 1 (glTF's matrices are affine)");
  }
  return m;
}

void ReadTransform(const JsonReader& r, GltfNode& node) {
  const std::optional<JsonReader> matrix = r.Find("matrix");
  if (matrix) {
    if (r.Find("translation") || r.Find("rotation") || r.Find("scale")) {
      r.Fail("a node with both \"matrix\" and translation, rotation or scale");
    }
    node.has_matrix = true;
    node.matrix = ReadMatrix(*matrix);
    return;
  }
  if (auto t = r.Find("translation")) node.translation = ReadVector<3>(*t);
  if (auto s = r.Find("scale")) node.scale = ReadVector<3>(*s);
  if (auto q = r.Find("rotation")) {
    node.rotation = ReadVector<4>(*q);
    const double length = glm::length(node.rotation);
    // Exporters write quaternions rounded to a few digits: normalised here, as engines do.
    if (!(length > 1e-6)) q->Fail("a rotation quaternion of length 0");
    node.rotation /= length;
  }
}

GltfNode ReadNode(const JsonReader& r, const GltfDocument& doc, std::size_t node_count) {
  r.ExpectObject();
  GltfNode node;
  if (auto name = r.Find("name")) node.name = name->String();
  ReadTransform(r, node);
  if (auto mesh = r.Find("mesh")) node.mesh = ReadIndex(*mesh, doc.meshes.size(), "meshes");
  if (auto camera = r.Find("camera")) node.camera = ReadIndex(*camera, doc.cameras.size(), "cameras");
  node.skinned = r.Find("skin").has_value();
  if (auto children = r.Find("children")) {
    children->ForEachElement([&](const JsonReader& c) { node.children.push_back(ReadIndex(c, node_count, "nodes")); });
  }
  return node;
}

std::string NodeName(const GltfDocument& doc, std::size_t i) {
  return "node " + std::to_string(i) + (doc.nodes[i].name.empty() ? "" : " \"" + doc.nodes[i].name + "\"");
}

// Each child names its parent; a second parent is refused.
void LinkParents(const JsonReader& nodes, GltfDocument& doc) {
  std::size_t i = 0;
  nodes.ForEachElement([&](const JsonReader& r) {
    for (const std::size_t child : doc.nodes[i].children) {
      std::optional<std::size_t>& parent = doc.nodes[child].parent;
      if (parent) {
        r.Required("children")
            .Fail(NodeName(doc, child) + " has two parents, " + NodeName(doc, *parent) + " and " + NodeName(doc, i) +
                  ": glTF's nodes form a forest");
      }
      parent = i;
    }
    ++i;
  });
}

// Walks up from every node: a walk that meets itself is a cycle; one longer than the limit is
// too deep. Each node is walked once (depth[] remembers it), so this is linear.
void CheckForest(const JsonReader& nodes, const GltfLimits& limits, const GltfDocument& doc) {
  constexpr std::size_t kUnknown = 0, kWalking = static_cast<std::size_t>(-1);
  std::vector<std::size_t> depth(doc.nodes.size(), kUnknown);  // 1 for a root
  std::vector<std::size_t> path;
  for (std::size_t start = 0; start < doc.nodes.size(); ++start) {
    path.clear();
    std::size_t at = start;
    while (depth[at] == kUnknown) {
      depth[at] = kWalking;
      path.push_back(at);
      if (!doc.nodes[at].parent) break;
      at = *doc.nodes[at].parent;
    }
    if (depth[at] == kWalking && doc.nodes[at].parent) {
      nodes.Fail(NodeName(doc, at) + " is its own ancestor: the nodes' children form a cycle");
    }
    std::size_t below = depth[at] == kWalking ? 0 : depth[at];
    for (auto it = path.rbegin(); it != path.rend(); ++it) {
      depth[*it] = ++below;
      if (below > limits.node_depth) {
        nodes.Fail(NodeName(doc, *it) + " lies more than " + std::to_string(limits.node_depth) +
                   " nodes below its root");
      }
    }
  }
}

void ReadScenes(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc) {
  if (const std::optional<JsonReader> scenes = ReadArray(root, "scenes", limits)) {
    scenes->ForEachElement([&](const JsonReader& r) {
      r.ExpectObject();
      GltfSceneRoots scene;
      if (auto name = r.Find("name")) scene.name = name->String();
      if (auto nodes = r.Find("nodes")) {
        nodes->ForEachElement([&](const JsonReader& n) {
          const std::size_t node = ReadIndex(n, doc.nodes.size(), "nodes");
          if (doc.nodes[node].parent) {
            n.Fail(NodeName(doc, node) + " is a child of " + NodeName(doc, *doc.nodes[node].parent) + ", not a root");
          }
          scene.nodes.push_back(node);
        });
      }
      doc.scenes.push_back(std::move(scene));
    });
  }
  if (auto scene = root.Find("scene")) doc.default_scene = ReadIndex(*scene, doc.scenes.size(), "scenes");
}

}  // namespace

void ReadNodesAndScenes(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc) {
  if (const std::optional<JsonReader> nodes = ReadArray(root, "nodes", limits)) {
    const std::size_t count = nodes->ExpectArray();
    if (count > limits.nodes) nodes->Fail("more than " + std::to_string(limits.nodes) + " nodes: refused");
    doc.nodes.reserve(count);
    nodes->ForEachElement([&](const JsonReader& r) { doc.nodes.push_back(ReadNode(r, doc, count)); });
    LinkParents(*nodes, doc);
    CheckForest(*nodes, limits, doc);
  }
  ReadScenes(root, limits, doc);
}

}  // namespace twinraster::gltf
