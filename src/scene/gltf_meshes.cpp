// The glTF reader's materials, meshes and cameras (gltf_parse.hpp).
#include "base/counted.hpp"
#include "scene/gltf_parse.hpp"

#include <cmath>
#include <numbers>
#include <string_view>

namespace twinraster::gltf {

namespace {

std::string NameOf(const JsonReader& r) {
  const std::optional<JsonReader> name = r.Find("name");
  return name ? name->String() : std::string();
}

bool NamesTexture(const JsonReader& material) {
  for (const char* key : {"normalTexture", "occlusionTexture", "emissiveTexture"}) {
    if (material.Find(key)) return true;
  }
  if (auto pbr = material.Find("pbrMetallicRoughness")) {
    pbr->ExpectObject();
    return pbr->Find("baseColorTexture").has_value() || pbr->Find("metallicRoughnessTexture").has_value();
  }
  return false;
}

glm::dvec4 ReadBaseColour(const JsonReader& material) {
  const std::optional<JsonReader> pbr = material.Find("pbrMetallicRoughness");
  if (!pbr) return {1, 1, 1, 1};
  const std::optional<JsonReader> factor = pbr->Find("baseColorFactor");
  if (!factor) return {1, 1, 1, 1};
  factor->ExpectArray(4);
  glm::dvec4 colour(1.0);
  std::size_t k = 0;
  factor->ForEachElement([&](const JsonReader& c) {
    const double value = c.Number();
    if (value < 0 || value > 1) c.Fail("a colour factor outside [0, 1]");
    colour[static_cast<glm::length_t>(k++)] = value;
  });
  return colour;
}

bool IsUnlit(const JsonReader& material) {
  const std::optional<JsonReader> extensions = material.Find("extensions");
  if (!extensions) return false;
  extensions->ExpectObject();
  return extensions->Find("KHR_materials_unlit").has_value();
}

// An attribute's accessor, checked to be of a kind the drawing reads: `what` names the kinds.
std::size_t ReadAttribute(const JsonReader& r, const GltfDocument& doc, bool (*fits)(const GltfAccessor&),
                          const std::string& what) {
  const std::size_t index = ReadIndex(r, doc.accessors.size(), "accessors");
  const GltfAccessor& a = doc.accessors[index];
  if (!fits(a)) {
    r.Fail("accessor " + std::to_string(index) + " is " + a.type + " of component type " +
           std::to_string(static_cast<std::uint32_t>(a.component)) + (a.normalized ? " (normalized)" : "") +
           "; this attribute must be " + what);
  }
  return index;
}

bool IsFloatVec3(const GltfAccessor& a) { return a.component == GltfComponent::kFloat && a.type == "VEC3"; }
bool IsColour(const GltfAccessor& a) {
  const bool vec = a.type == "VEC3" || a.type == "VEC4";
  const bool unorm =
      a.normalized && (a.component == GltfComponent::kUnsignedByte || a.component == GltfComponent::kUnsignedShort);
  return vec && (a.component == GltfComponent::kFloat || unorm);
}
bool IsIndex(const GltfAccessor& a) {
  const bool unsigned_int = a.component == GltfComponent::kUnsignedByte ||
                            a.component == GltfComponent::kUnsignedShort || a.component == GltfComponent::kUnsignedInt;
  return a.type == "SCALAR" && unsigned_int && !a.normalized;
}

void ReadAttributes(const JsonReader& attributes, const GltfDocument& doc, GltfPrimitive& p) {
  attributes.ExpectObject();
  for (const std::string_view key : attributes.Keys()) {
    const JsonReader r = *attributes.Find(key);
    if (key == "POSITION") {
      p.position = ReadAttribute(r, doc, IsFloatVec3, "VEC3 of FLOAT (KHR_mesh_quantization is not implemented)");
    } else if (key == "NORMAL") {
      p.normal = ReadAttribute(r, doc, IsFloatVec3, "VEC3 of FLOAT");
    } else if (key == "COLOR_0") {
      p.colour =
          ReadAttribute(r, doc, IsColour, "VEC3 or VEC4 of FLOAT, or of normalized UNSIGNED_BYTE or UNSIGNED_SHORT");
    } else {
      ReadIndex(r, doc.accessors.size(), "accessors");
      p.textured = p.textured || key.substr(0, 9) == "TEXCOORD_";
      p.skinned = p.skinned || key.substr(0, 7) == "JOINTS_" || key.substr(0, 8) == "WEIGHTS_";
    }
  }
  if (!attributes.Find("POSITION")) attributes.Fail("no POSITION: a primitive without positions cannot be drawn");
  const std::uint64_t count = doc.accessors[p.position].count;
  for (const std::string_view key : attributes.Keys()) {
    const JsonReader r = *attributes.Find(key);
    const std::uint64_t n = doc.accessors[ReadIndex(r, doc.accessors.size(), "accessors")].count;
    if (n != count) {
      r.Fail(std::string(key) + " has " + Counted(n, "element") + ", POSITION " + std::to_string(count) +
             ": every attribute of a primitive has the same count");
    }
  }
}

GltfPrimitive ReadPrimitive(const JsonReader& r, const GltfDocument& doc) {
  r.ExpectObject();
  GltfPrimitive p;
  ReadAttributes(r.Required("attributes"), doc, p);
  if (auto indices = r.Find("indices")) {
    p.indices = ReadAttribute(*indices, doc, IsIndex, "SCALAR of UNSIGNED_BYTE, UNSIGNED_SHORT or UNSIGNED_INT");
  }
  if (auto material = r.Find("material")) p.material = ReadIndex(*material, doc.materials.size(), "materials");
  if (auto mode = r.Find("mode")) p.mode = static_cast<GltfMode>(mode->Integer(0, 6));
  p.morph_targets = r.Find("targets").has_value();
  return p;
}

GltfCamera ReadPerspective(const JsonReader& r, GltfCamera camera) {
  r.ExpectObject();
  camera.yfov = r.Required("yfov").Positive();
  // The chapter's viewport is 2·tan(yfov/2) high at d = 1: it must be finite.
  if (camera.yfov >= std::numbers::pi) r.Required("yfov").Fail("a vertical field of view of π or more");
  if (auto aspect = r.Find("aspectRatio")) camera.aspect_ratio = aspect->Positive();
  camera.znear = r.Required("znear").Positive();
  if (auto zfar = r.Find("zfar")) {
    camera.zfar = zfar->Positive();
    if (*camera.zfar <= camera.znear) zfar->Fail("zfar must be greater than znear");
  }
  return camera;
}

GltfCamera ReadOrthographic(const JsonReader& r, GltfCamera camera) {
  r.ExpectObject();
  camera.orthographic = true;
  camera.xmag = r.Required("xmag").Positive();
  camera.ymag = r.Required("ymag").Positive();
  camera.znear = r.Required("znear").Number();
  if (camera.znear < 0) r.Required("znear").Fail("znear must not be negative");
  camera.zfar = r.Required("zfar").Positive();
  if (*camera.zfar <= camera.znear) r.Required("zfar").Fail("zfar must be greater than znear");
  return camera;
}

}  // namespace

void ReadMaterials(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc) {
  const std::optional<JsonReader> array = ReadArray(root, "materials", limits);
  if (!array) return;
  array->ForEachElement([&](const JsonReader& r) {
    r.ExpectObject();
    GltfMaterial m;
    m.name = NameOf(r);
    m.base_colour = ReadBaseColour(r);
    m.unlit = IsUnlit(r);
    m.textured = NamesTexture(r);
    if (auto sided = r.Find("doubleSided")) m.double_sided = sided->Boolean();
    doc.materials.push_back(m);
  });
}

void ReadMeshes(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc) {
  const std::optional<JsonReader> array = ReadArray(root, "meshes", limits);
  if (!array) return;
  std::size_t total = 0;
  array->ForEachElement([&](const JsonReader& r) {
    r.ExpectObject();
    GltfMesh mesh;
    mesh.name = NameOf(r);
    const JsonReader primitives = r.Required("primitives");
    if (primitives.ExpectArray() == 0) primitives.Fail("a mesh without primitives");
    total += primitives.ExpectArray();
    if (total > limits.primitives) {
      primitives.Fail("more than " + std::to_string(limits.primitives) +
                      " primitives over all meshes: refused (each becomes a model of its own)");
    }
    primitives.ForEachElement([&](const JsonReader& p) { mesh.primitives.push_back(ReadPrimitive(p, doc)); });
    doc.meshes.push_back(std::move(mesh));
  });
}

void ReadCameras(const JsonReader& root, const GltfLimits& limits, GltfDocument& doc) {
  const std::optional<JsonReader> array = ReadArray(root, "cameras", limits);
  if (!array) return;
  array->ForEachElement([&](const JsonReader& r) {
    r.ExpectObject();
    GltfCamera camera;
    camera.name = NameOf(r);
    const std::string type = r.Required("type").String();
    if (type == "perspective") {
      doc.cameras.push_back(ReadPerspective(r.Required("perspective"), camera));
    } else if (type == "orthographic") {
      doc.cameras.push_back(ReadOrthographic(r.Required("orthographic"), camera));
    } else {
      r.Required("type").Fail("expected \"perspective\" or \"orthographic\", found \"" + type + "\"");
    }
  });
}

}  // namespace twinraster::gltf
