// A glTF primitive as a model (gltf_build.hpp).
#include "base/counted.hpp"
#include "scene/gltf_accessors.hpp"
#include "scene/gltf_build.hpp"
#include "scene/json_reader.hpp"  // kMaxMagnitude: a glTF file's numbers are bounded as a scene's are
#include "scene/scene_error.hpp"
#include "scene/srgb.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <sstream>

namespace twinraster::gltf {

namespace {

std::string PrimitivePath(std::size_t mesh, std::size_t primitive) {
  return "meshes[" + std::to_string(mesh) + "].primitives[" + std::to_string(primitive) + "]";
}

const char* ModeName(GltfMode mode) {
  switch (mode) {
    case GltfMode::kPoints: return "POINTS";
    case GltfMode::kLines: return "LINES";
    case GltfMode::kLineLoop: return "LINE_LOOP";
    case GltfMode::kLineStrip: return "LINE_STRIP";
    case GltfMode::kTriangles: return "TRIANGLES";
    case GltfMode::kTriangleStrip: return "TRIANGLE_STRIP";
    case GltfMode::kTriangleFan: return "TRIANGLE_FAN";
  }
  return "?";
}

// A copy (a few words), so that no reference outlives the `where` built for it.
GltfAccessor Unsparse(const GltfDocument& doc, std::size_t accessor, const std::string& where) {
  const GltfAccessor& a = doc.accessors[accessor];
  if (a.sparse) {
    throw SceneError(doc.file, where,
                     "accessor " + std::to_string(accessor) + " is sparse; twinraster does not read sparse accessors");
  }
  return a;
}

// glTF forbids NaN and infinite values in accessors (glTF 2.0, 3.6.2.2), and a scene's numbers
// are bounded (kMaxMagnitude): a value past either would reach the chain as NaN, so the file is
// refused, naming the element.
template <class Vector>
std::vector<Vector> Bounded(const GltfDocument& doc, std::vector<Vector> values, const std::string& where) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    for (glm::length_t k = 0; k < Vector::length(); ++k) {
      const double x = values[i][k];
      if (std::isfinite(x) && std::abs(x) <= kMaxMagnitude) continue;
      std::ostringstream s;
      s << "element " << i << ", component " << k << ", is " << x;
      if (std::isfinite(x))
        s << ": absurd (magnitude above " << kMaxMagnitude << ")";
      else
        s << ": glTF forbids NaN and infinite values (glTF 2.0, 3.6.2.2)";
      throw SceneError(doc.file, where, s.str());
    }
  }
  return values;
}

// The primitive's vertex indices in order: its index accessor's, each checked, or 0, 1, 2, ...
std::vector<std::uint32_t> VertexOrder(const GltfDocument& doc, const GltfPrimitive& p, std::uint64_t vertices,
                                       const std::string& where) {
  if (!p.indices) {
    std::vector<std::uint32_t> order(static_cast<std::size_t>(vertices));
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<std::uint32_t>(i);
    return order;
  }
  std::vector<std::uint32_t> order = ReadIndices(doc, Unsparse(doc, *p.indices, where + ".indices"));
  for (std::size_t i = 0; i < order.size(); ++i) {
    if (order[i] >= vertices) {
      throw SceneError(doc.file, where + ".indices",
                       "element " + std::to_string(i) + " is vertex " + std::to_string(order[i]) + ", past the " +
                           Counted(vertices, "vertex", "vertices") + " of POSITION");
    }
  }
  return order;
}

// Triangle i of a list, strip or fan, as the spec (and Vulkan) orders its corners.
std::vector<std::array<std::uint32_t, 3>> Assemble(GltfMode mode, const std::vector<std::uint32_t>& v) {
  std::vector<std::array<std::uint32_t, 3>> out;
  const std::size_t n = v.size();
  if (mode == GltfMode::kTriangles) {
    out.reserve(n / 3);
    for (std::size_t i = 0; i + 2 < n; i += 3) out.push_back({v[i], v[i + 1], v[i + 2]});
  } else if (mode == GltfMode::kTriangleStrip) {
    out.reserve(n > 2 ? n - 2 : 0);
    for (std::size_t i = 0; i + 2 < n; ++i) out.push_back({v[i], v[i + 1 + i % 2], v[i + 2 - i % 2]});
  } else if (mode == GltfMode::kTriangleFan) {
    out.reserve(n > 2 ? n - 2 : 0);
    for (std::size_t i = 0; i + 2 < n; ++i) out.push_back({v[i + 1], v[i + 2], v[0]});
  }
  return out;
}

// Each triangle's normal, cross(v1 - v0, v2 - v0) (outward for glTF's counter-clockwise front
// faces), at all three of its corners.
void FaceNormals(Model& model) {
  model.normals.clear();
  model.triangle_normals.clear();
  for (const Triangle& t : model.triangles) {
    const auto n = static_cast<std::uint32_t>(model.normals.size());
    const glm::dvec3& a = model.vertices[t.v[0]];
    model.normals.push_back(glm::cross(model.vertices[t.v[1]] - a, model.vertices[t.v[2]] - a));
    model.triangle_normals.push_back({n, n, n});
  }
}

std::string ModelName(const GltfDocument& doc, std::size_t mesh, std::size_t primitive) {
  const GltfMesh& m = doc.meshes[mesh];
  std::string name = m.name.empty() ? "mesh " + std::to_string(mesh) : m.name;
  if (m.primitives.size() > 1) name += " primitive " + std::to_string(primitive);
  return name;
}

}  // namespace

std::optional<Model> PrimitiveModel(const GltfDocument& doc, std::size_t mesh, std::size_t primitive,
                                    std::vector<std::string>& notes) {
  const GltfPrimitive& p = doc.meshes[mesh].primitives[primitive];
  const std::string where = PrimitivePath(mesh, primitive);
  const bool triangles =
      p.mode == GltfMode::kTriangles || p.mode == GltfMode::kTriangleStrip || p.mode == GltfMode::kTriangleFan;
  if (!triangles) {
    notes.push_back(where + ": " + ModeName(p.mode) + " not drawn (twinraster draws triangles only)");
    return std::nullopt;
  }
  const GltfAccessor positions = Unsparse(doc, p.position, where + ".attributes.POSITION");
  const std::vector<std::array<std::uint32_t, 3>> corners =
      Assemble(p.mode, VertexOrder(doc, p, positions.count, where));
  if (corners.empty()) {
    notes.push_back(where + ": " + ModeName(p.mode) + " of fewer than 3 vertices: nothing to draw");
    return std::nullopt;
  }
  const GltfMaterial material = p.material ? doc.materials[*p.material] : GltfMaterial{};
  Model model;
  model.name = ModelName(doc, mesh, primitive);
  model.source = doc.file;
  model.vertices = Bounded(doc, ReadVec3s(doc, positions), where + ".attributes.POSITION");
  const Rgb8 colour = SrgbColour(material.base_colour);
  model.triangles.reserve(corners.size());
  for (const auto& c : corners) model.triangles.push_back(Triangle{c, colour});
  if (p.colour) {
    // The spec's base colour is baseColorFactor times COLOR_0, both linear: multiplied in double,
    // then encoded once per vertex; the rasterizer interpolates the bytes (docs/scene-format.md).
    const std::string colour_where = where + ".attributes.COLOR_0";
    const std::vector<glm::dvec4> colours =
        Bounded(doc, ReadColours(doc, Unsparse(doc, *p.colour, colour_where)), colour_where);
    model.vertex_colours.reserve(colours.size());
    for (const glm::dvec4& c : colours) model.vertex_colours.push_back(SrgbColour(c * material.base_colour));
  }
  if (p.normal) {
    const std::string normal_where = where + ".attributes.NORMAL";
    model.normals = Bounded(doc, ReadVec3s(doc, Unsparse(doc, *p.normal, normal_where)), normal_where);
    model.triangle_normals = corners;  // a vertex's normal has the vertex's index
  }
  // Unlit materials keep their colour; the rest take the headlight, with their normals
  // (Gouraud) or, as the spec asks of a primitive without normals, flat. Flat with COLOR_0 would
  // flatten the colours too (a flat output takes the provoking vertex's), so such a primitive is
  // lit per corner with its face's normal at every corner: one light, interpolated colours.
  model.shading = material.unlit ? Shading::kUnlit : p.normal ? Shading::kGouraud : Shading::kFlat;
  if (model.shading == Shading::kFlat && !model.vertex_colours.empty()) {
    FaceNormals(model);
    model.shading = Shading::kGouraud;
  }
  return model;
}

}  // namespace twinraster::gltf
