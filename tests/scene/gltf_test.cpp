// glTF 2.0 read into the chapter's scene: the node chain composed as the spec says (T·R·S, column-
// major matrices, parents before children, then the mirror), cameras, primitive modes in the
// spec's vertex order, index sizes and interleaving, colours; and every refusal a hostile file
// earns, each naming where. The files are built here, byte by byte, from the spec's layout.
#include "scene/gltf_document.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/srgb.hpp"
#include "support/catch.hpp"
#include "support/gltf_bytes.hpp"
#include "support/test_support.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

using namespace twinraster;
using Json = nlohmann::json;

namespace {

using test::AppendBytes;
using test::Base64;

// One buffer: a unit right triangle's three float positions (bytes 0-35), then 16-bit indices
// 0 1 2 (bytes 36-41, padded to 44).
std::vector<std::uint8_t> TriangleBytes() {
  std::vector<std::uint8_t> b;
  for (const float f : {0.f, 0.f, 0.f, 1.f, 0.f, 0.f, 0.f, 1.f, 0.f}) AppendBytes(b, f);
  for (const int i : {0, 1, 2, 0}) AppendBytes(b, static_cast<std::uint16_t>(i));
  return b;
}

// A document around TriangleBytes with one mesh; `nodes` and `scenes` as given.
Json TriangleDocument(const Json& nodes) {
  const std::vector<std::uint8_t> bytes = TriangleBytes();
  return Json{
      {"asset", {{"version", "2.0"}}},
      {"buffers", {{{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + Base64(bytes)}}}},
      {"bufferViews",
       {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
        {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 6}}}},
      {"accessors",
       {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
        {{"bufferView", 1}, {"componentType", 5123}, {"count", 3}, {"type", "SCALAR"}}}},
      {"meshes", {{{"name", "tri"}, {"primitives", {{{"attributes", {{"POSITION", 0}}}, {"indices", 1}}}}}}},
      {"nodes", nodes},
      {"scenes", {{{"nodes", {0}}}}},
  };
}

GltfDocument Parse(const Json& doc, const std::filesystem::path& directory = {}) {
  const std::string text = doc.dump();
  return ParseGltf(std::vector<std::uint8_t>(text.begin(), text.end()), "t.gltf", directory);
}

Scene SceneOf(const Json& doc, const SceneChoice& choice = {}) { return GltfScene(Parse(doc), choice, "t"); }

// The refusal's where and problem, for matching.
std::string Refusal(const Json& doc, const SceneChoice& choice = {}) {
  try {
    SceneOf(doc, choice);
  } catch (const SceneError& e) {
    CHECK(e.file() == "t.gltf");
    return e.where() + ": " + e.problem();
  }
  return "(no error)";
}

// M_Model the way chain/ composes a list: each step applied after the ones before.
glm::dmat4 Composed(const Transform& t) {
  glm::dmat4 m(1.0);
  for (const TransformStep& s : *t.steps) {
    glm::dmat4 step = s.matrix;
    if (s.kind == TransformStep::Kind::kScale) {
      step = glm::dmat4(1.0);
      for (int i = 0; i < 3; ++i) step[i][i] = s.vector[i];
    }
    m = step * m;
  }
  return m;
}

void RequireClose(const glm::dmat4& a, const glm::dmat4& b) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) REQUIRE(std::abs(a[c][r] - b[c][r]) < 1e-12);
}

}  // namespace

TEST_CASE("glTF: M_Model is the mirror times the node chain from the root, each node T·R·S") {
  // Root: translation (1, 2, 3). Child: a quarter turn about +Y (right-handed: +Z to +X) and scale (2, 1, 1).
  const double h = std::sqrt(0.5);
  const Json nodes = {{{"translation", {1, 2, 3}}, {"children", {1}}},
                      {{"rotation", {0, h, 0, h}}, {"scale", {2, 1, 1}}, {"mesh", 0}, {"name", "child"}}};
  const Scene scene = SceneOf(TriangleDocument(nodes));
  REQUIRE(scene.instances.size() == 1);
  const Transform& t = scene.instances[0].transform;
  REQUIRE(t.steps->size() == 3);  // child, root, mirror
  CHECK((*t.steps)[0].label == "node 1 \"child\" (T·R·S)");
  CHECK((*t.steps)[1].label == "node 0 (T·R·S)");
  // By hand: the child maps x to 2·(rotated x) = (0, 0, -2), y to y, z to +x; the root adds (1, 2, 3);
  // the mirror negates z.
  const glm::dmat4 expected(glm::dvec4(0, 0, 2, 0), glm::dvec4(0, 1, 0, 0), glm::dvec4(1, 0, 0, 0),
                            glm::dvec4(1, 2, -3, 1));
  RequireClose(Composed(t), expected);
}

TEST_CASE("glTF: a node matrix is read column-major") {
  const Json nodes = {{{"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 5, 6, 7, 1}}, {"mesh", 0}}};
  const Scene scene = SceneOf(TriangleDocument(nodes));
  const glm::dmat4 m = (*scene.instances[0].transform.steps)[0].matrix;
  CHECK(m[3] == glm::dvec4(5, 6, 7, 1));
  CHECK((*scene.instances[0].transform.steps)[0].label == "node 0 (matrix)");
  Json bad = TriangleDocument({{{"matrix", {1, 0, 0, 5, 0, 1, 0, 6, 0, 0, 1, 7, 0, 0, 0, 1}}, {"mesh", 0}}});
  CHECK_THAT(Refusal(bad), HasSubstring("nodes[0].matrix: a node matrix's last row must be 0 0 0 1"));
}

TEST_CASE("glTF: strips and fans keep the spec's vertex order, so the first corner is the provoking vertex") {
  std::vector<std::uint8_t> bytes;
  for (int i = 0; i < 5; ++i) {
    for (const float f : {static_cast<float>(i), static_cast<float>(i % 2), 0.f}) AppendBytes(bytes, f);
  }
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", "data:application/gltf-buffer;base64," + Base64(bytes)}};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", bytes.size()}}};
  doc["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 5}, {"type", "VEC3"}}};
  const auto triangles = [&](int mode) {
    doc["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 0}}}, {"mode", mode}}};
    std::vector<std::array<std::uint32_t, 3>> out;
    const Scene scene = SceneOf(doc);
    for (const Triangle& t : scene.models[0].triangles) out.push_back(t.v);
    return out;
  };
  using T = std::vector<std::array<std::uint32_t, 3>>;
  CHECK(triangles(4) == T{{0, 1, 2}});
  CHECK(triangles(5) == T{{0, 1, 2}, {1, 3, 2}, {2, 3, 4}});  // odd triangles swap their last two
  CHECK(triangles(6) == T{{1, 2, 0}, {2, 3, 0}, {3, 4, 0}});
  // Points and lines are not drawn, and a file of nothing else is refused with the reason.
  doc["meshes"][0]["primitives"][0]["mode"] = 1;
  CHECK_THAT(Refusal(doc), HasSubstring("nothing to draw"));
  CHECK_THAT(Refusal(doc), HasSubstring("LINES not drawn"));
}

TEST_CASE("glTF: 8-, 16- and 32-bit indices, and interleaved positions and normals") {
  std::vector<std::uint8_t> bytes;
  // Three vertices, each a position then a normal (stride 24).
  for (int v = 0; v < 3; ++v) {
    for (const float f : {v == 1 ? 1.f : 0.f, v == 2 ? 1.f : 0.f, 0.f, 0.f, 0.f, 1.f}) AppendBytes(bytes, f);
  }
  const std::size_t indices_at = bytes.size();
  for (const std::uint32_t i : {2u, 1u, 0u}) AppendBytes(bytes, i);
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + Base64(bytes)}};
  doc["bufferViews"] = {{{"buffer", 0}, {"byteLength", indices_at}, {"byteStride", 24}},
                        {{"buffer", 0}, {"byteOffset", indices_at}, {"byteLength", 12}}};
  doc["accessors"] = {{{"bufferView", 0}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                      {{"bufferView", 0}, {"byteOffset", 12}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}},
                      {{"bufferView", 1}, {"componentType", 5125}, {"count", 3}, {"type", "SCALAR"}}};
  doc["meshes"][0]["primitives"] = {{{"attributes", {{"POSITION", 0}, {"NORMAL", 1}}}, {"indices", 2}}};
  Scene scene = SceneOf(doc);
  const Model& m = scene.models[0];
  CHECK(m.triangles[0].v == std::array<std::uint32_t, 3>{2, 1, 0});
  CHECK(m.vertices[1] == glm::dvec3(1, 0, 0));
  CHECK(m.vertices[2] == glm::dvec3(0, 1, 0));
  CHECK(m.normals[2] == glm::dvec3(0, 0, 1));
  CHECK(m.shading == Shading::kGouraud);

  // The same indices as bytes, and as 16-bit words.
  for (const int component : {5121, 5123}) {
    std::vector<std::uint8_t> more = bytes;
    more.resize(indices_at);
    for (const std::uint32_t i : {2u, 1u, 0u}) {
      if (component == 5121)
        AppendBytes(more, static_cast<std::uint8_t>(i));
      else
        AppendBytes(more, static_cast<std::uint16_t>(i));
    }
    doc["buffers"][0] = {{"byteLength", more.size()}, {"uri", "data:application/octet-stream;base64," + Base64(more)}};
    doc["bufferViews"][1]["byteLength"] = more.size() - indices_at;
    doc["accessors"][2]["componentType"] = component;
    CHECK(SceneOf(doc).models[0].triangles[0].v == std::array<std::uint32_t, 3>{2, 1, 0});
  }
}

TEST_CASE("glTF: NaN, infinite and absurd values are refused, naming the accessor's element") {
  // The spec forbids NaN and infinities in accessors (glTF 2.0, 3.6.2.2); past 1e12 a scene's
  // numbers are refused, as in a scene file. Either would reach the framing and the chain as NaN.
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  for (const auto& [bad, problem] :
       std::vector<std::pair<float, std::string>>{{nan, "is nan: glTF forbids NaN and infinite values"},
                                                  {-inf, "is -inf: glTF forbids NaN and infinite values"},
                                                  {1e13f, "is 1e+13: absurd (magnitude above 1e+12)"}}) {
    INFO(problem);
    std::vector<std::uint8_t> bytes = TriangleBytes();
    std::memcpy(bytes.data() + 4 * 4, &bad, 4);  // vertex 1, component y
    Json doc = TriangleDocument({{{"mesh", 0}}});
    doc["buffers"][0]["uri"] = "data:application/octet-stream;base64," + Base64(bytes);
    CHECK_THAT(Refusal(doc),
               HasSubstring("meshes[0].primitives[0].attributes.POSITION: element 1, component 1, " + problem));
    // The same value as a normal: good positions (bytes 0-35), the bad ones as normals (36-71).
    doc = TriangleDocument({{{"mesh", 0}}});
    doc["accessors"].push_back({{"bufferView", 2}, {"componentType", 5126}, {"count", 3}, {"type", "VEC3"}});
    const std::vector<std::uint8_t> good = TriangleBytes();
    bytes.insert(bytes.begin(), good.begin(), good.begin() + 36);
    doc["buffers"][0] = {{"byteLength", bytes.size()},
                         {"uri", "data:application/octet-stream;base64," + Base64(bytes)}};
    doc["bufferViews"] = {{{"buffer", 0}, {"byteOffset", 0}, {"byteLength", 36}},
                          {{"buffer", 0}, {"byteOffset", 72}, {"byteLength", 6}},
                          {{"buffer", 0}, {"byteOffset", 36}, {"byteLength", 36}}};
    doc["meshes"][0]["primitives"][0]["attributes"]["NORMAL"] = 2;
    CHECK_THAT(Refusal(doc), HasSubstring("attributes.NORMAL: element 1, component 1, " + problem));
  }
}

TEST_CASE("glTF: a primitive without normals is lit flat, an unlit material is unlit, colours become sRGB bytes") {
  Json doc = TriangleDocument({{{"mesh", 0}}});
  CHECK(SceneOf(doc).models[0].shading == Shading::kFlat);
  doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.2158605, 1.0, 0.0, 1.0}}}},
                       {"extensions", {{"KHR_materials_unlit", Json::object()}}}}};
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  const Model m = SceneOf(doc).models[0];
  CHECK(m.shading == Shading::kUnlit);
  CHECK(m.triangles[0].colour == Rgb8{128, 255, 0});
}

TEST_CASE("glTF: COLOR_0 times baseColorFactor is each vertex's colour, encoded once per vertex") {
  std::vector<std::uint8_t> bytes = TriangleBytes();
  const std::size_t colours_at = bytes.size();
  for (const int c : {255, 0, 0, 255, 0, 255, 0, 255, 0, 0, 255, 255}) bytes.push_back(static_cast<std::uint8_t>(c));
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["buffers"][0] = {{"byteLength", bytes.size()}, {"uri", "data:application/octet-stream;base64," + Base64(bytes)}};
  doc["bufferViews"].push_back({{"buffer", 0}, {"byteOffset", colours_at}, {"byteLength", 12}});
  doc["accessors"].push_back(
      {{"bufferView", 2}, {"componentType", 5121}, {"normalized", true}, {"count", 3}, {"type", "VEC4"}});
  doc["meshes"][0]["primitives"][0]["attributes"]["COLOR_0"] = 2;
  doc["materials"] = {{{"pbrMetallicRoughness", {{"baseColorFactor", {0.5, 1.0, 0.2158605, 1.0}}}}}};
  doc["meshes"][0]["primitives"][0]["material"] = 0;
  const Scene scene = SceneOf(doc);
  const Model& m = scene.models[0];
  REQUIRE(m.vertex_colours.size() == 3);
  CHECK(m.vertex_colours[0] == Rgb8{188, 0, 0});
  CHECK(m.vertex_colours[1] == Rgb8{0, 255, 0});
  CHECK(m.vertex_colours[2] == Rgb8{0, 0, 128});
  CHECK(m.triangles[0].colour == Rgb8{188, 255, 128});  // the material's, for a wireframe
  // A COLOR_0 of signed bytes is not one the spec allows.
  doc["accessors"][2]["componentType"] = 5120;
  CHECK_THAT(Refusal(doc), HasSubstring("COLOR_0: accessor 2 is VEC4 of component type 5120 (normalized)"));
}

TEST_CASE("glTF: linear colours are encoded with sRGB's transfer function and rounded") {
  CHECK(SrgbByte(0.0) == 0);
  CHECK(SrgbByte(1.0) == 255);
  CHECK(SrgbByte(0.5) == 188);        // 1.055 · 0.5^(1/2.4) - 0.055 = 0.7354
  CHECK(SrgbByte(0.2158605) == 128);  // sRGB's middle grey
  CHECK(SrgbByte(0.002) == 7);        // the linear segment: 12.92 · 0.002 · 255 = 6.6
  CHECK(SrgbByte(-1.0) == 0);
  CHECK(SrgbByte(2.0) == 255);
  CHECK(SrgbByte(std::numeric_limits<double>::quiet_NaN()) == 0);
}

TEST_CASE("glTF: a perspective camera keeps its field of view and aspect ratio, and without zfar its far is infinite") {
  Json doc = TriangleDocument({{{"mesh", 0}}, {{"camera", 0}, {"translation", {0, 0, 5}}}});
  doc["scenes"][0]["nodes"] = {0, 1};
  doc["cameras"] = {{{"type", "perspective"},
                     {"name", "wide"},
                     {"perspective", {{"yfov", 0.5}, {"aspectRatio", 2.0}, {"znear", 0.1}}}}};
  Scene scene = SceneOf(doc);
  CHECK(scene.canvas.width == 800);
  CHECK(scene.canvas.height == 400);
  CHECK(std::abs(scene.viewport.height - 2 * std::tan(0.25)) < 1e-15);
  CHECK(std::abs(scene.viewport.width - 4 * std::tan(0.25)) < 1e-15);
  CHECK(std::isinf(scene.depth.far));
  CHECK(scene.depth.near == 0.1);
  // glTF's camera at +5 z looking down -z is, mirrored, the chapter's at -5 z looking down +z.
  CHECK(scene.camera.position == glm::dvec3(0, 0, -5));
  CHECK(scene.camera.rotation == glm::dmat3(1.0));

  // A canvas of another shape widens the view, never crops or stretches it.
  scene = SceneOf(doc, SceneChoice{std::nullopt, std::nullopt, CanvasSize{400, 400}});
  CHECK(scene.canvas.width == 400);
  CHECK(std::abs(scene.viewport.width - 4 * std::tan(0.25)) < 1e-15);
  CHECK(std::abs(scene.viewport.height - 4 * std::tan(0.25)) < 1e-15);
  // Without an aspect ratio, the canvas's is used.
  doc["cameras"][0]["perspective"].erase("aspectRatio");
  scene = SceneOf(doc, SceneChoice{std::nullopt, std::nullopt, CanvasSize{300, 100}});
  CHECK(std::abs(scene.viewport.width - 3 * scene.viewport.height) < 1e-15);
  CHECK(std::abs(scene.viewport.height - 2 * std::tan(0.25)) < 1e-15);
}

TEST_CASE("glTF: --camera by index or name, orthographic cameras, and a camera asked for that is not there") {
  Json doc = TriangleDocument({{{"mesh", 0}}, {{"camera", 1}, {"translation", {0, 0, 5}}}, {{"camera", 0}}});
  doc["scenes"][0]["nodes"] = {0, 1, 2};
  doc["cameras"] = {
      {{"type", "perspective"}, {"name", "p"}, {"perspective", {{"yfov", 0.5}, {"znear", 0.1}, {"zfar", 10}}}},
      {{"type", "orthographic"},
       {"name", "o"},
       {"orthographic", {{"xmag", 3}, {"ymag", 1.5}, {"znear", 0}, {"zfar", 10}}}}};
  // The first camera node walked is node 1, camera 1.
  Scene scene = SceneOf(doc);
  CHECK(scene.viewport.projection == Projection::kOrthographic);
  CHECK(scene.viewport.width == 6);
  CHECK(scene.viewport.height == 3);
  CHECK(scene.canvas.height == 400);
  scene = SceneOf(doc, SceneChoice{"0", std::nullopt, std::nullopt});
  CHECK(scene.viewport.projection == Projection::kPerspective);
  CHECK(scene.depth.far == 10);
  scene = SceneOf(doc, SceneChoice{"o", std::nullopt, std::nullopt});
  CHECK(scene.viewport.projection == Projection::kOrthographic);
  CHECK_THAT(Refusal(doc, SceneChoice{"7", std::nullopt, std::nullopt}),
             HasSubstring("--camera 7 names no camera; the file's cameras: camera 0 \"p\", camera 1 \"o\""));
  doc["scenes"][0]["nodes"] = {0, 1};
  CHECK_THAT(Refusal(doc, SceneChoice{"p", std::nullopt, std::nullopt}),
             HasSubstring("camera 0 \"p\" is placed by no node"));
  CHECK_THAT(Refusal(doc, SceneChoice{std::nullopt, 3, std::nullopt}), HasSubstring("--scene 3: the file has 1 scene"));
}

TEST_CASE("glTF: without a camera the asset is framed as an OBJ file is") {
  const Scene scene = SceneOf(TriangleDocument({{{"mesh", 0}}}));
  CHECK(scene.canvas.width == 800);
  CHECK(scene.lighting.has_value());
  CHECK(std::isfinite(scene.depth.far));
}

TEST_CASE("glTF: the node graph must be a forest") {
  CHECK_THAT(Refusal(TriangleDocument({{{"mesh", 0}, {"children", {1}}}, {{"children", {0}}}})),
             HasSubstring("its own ancestor"));
  CHECK_THAT(Refusal(TriangleDocument({{{"mesh", 0}, {"children", {2}}}, {{"children", {2}}}, Json::object()})),
             HasSubstring("nodes[1].children: node 2 has two parents, node 0 and node 1"));
  CHECK_THAT(Refusal(TriangleDocument({{{"mesh", 0}, {"children", {0}}}})), HasSubstring("its own ancestor"));
  Json deep = Json::array();
  for (int i = 0; i < 300; ++i) deep.push_back(i + 1 < 300 ? Json{{"children", {i + 1}}} : Json{{"mesh", 0}});
  CHECK_THAT(Refusal(TriangleDocument(deep)), HasSubstring("more than 256 nodes below its root"));
  Json child_as_root = TriangleDocument({{{"mesh", 0}, {"children", {1}}}, Json::object()});
  child_as_root["scenes"][0]["nodes"] = {1};
  CHECK_THAT(Refusal(child_as_root), HasSubstring("scenes[0].nodes[0]: node 1 is a child of node 0, not a root"));
}

TEST_CASE("glTF: a lit mesh scaled to 0 is left out with a note, and one flattened to a plane is refused") {
  // A lit mesh needs the normal matrix, which a singular M_Model lacks: before this check such a
  // file reached the drawing and ended as an internal error (exit 4).
  const Json hidden = TriangleDocument({{{"mesh", 0}}, {{"mesh", 0}, {"scale", {0, 0, 0}}}});
  Json both = hidden;
  both["scenes"][0]["nodes"] = {0, 1};
  const Scene scene = SceneOf(both);
  CHECK(scene.instances.size() == 1);
  CHECK_THAT(scene.notes.front(), HasSubstring("1 lit primitive under a node chain scaled to 0: not drawn"));
  Json under_parent = TriangleDocument({{{"scale", {0, 0, 0}}, {"children", {1}}}, {{"mesh", 0}}});
  CHECK_THAT(Refusal(under_parent), HasSubstring("nothing to draw"));
  CHECK_THAT(Refusal(TriangleDocument({{{"mesh", 0}, {"scale", {1, 1, 0}}}})),
             HasSubstring("nodes[0]: a lit mesh whose node chain has no inverse"));
  Json matrix = TriangleDocument({{{"mesh", 0}, {"matrix", {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 1}}}});
  CHECK_THAT(Refusal(matrix), HasSubstring("nodes[0]: a lit mesh whose node chain has no inverse"));
  Json unlit = TriangleDocument({{{"mesh", 0}, {"scale", {1, 1, 0}}}});
  unlit["materials"] = {{{"extensions", {{"KHR_materials_unlit", Json::object()}}}}};
  unlit["meshes"][0]["primitives"][0]["material"] = 0;
  CHECK(SceneOf(unlit).instances.size() == 1);  // unlit: no normals, drawn as it is
}

TEST_CASE("glTF: every range is checked against the real bytes, with arithmetic that cannot wrap") {
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["bufferViews"][0]["byteLength"] = 100;
  CHECK_THAT(Refusal(doc), HasSubstring("bufferViews[0]: bytes 0 + 100 lie past the end of buffer 0 (44 bytes)"));
  doc = TriangleDocument({{{"mesh", 0}}});
  doc["accessors"][0]["count"] = 4;
  CHECK_THAT(Refusal(doc), HasSubstring("accessors[0]: 4 elements of 12 bytes"));
  doc["accessors"][0]["count"] = 1099511627776;  // 2^40: count · stride must not wrap
  CHECK_THAT(Refusal(doc), HasSubstring("run past the bufferView"));
  doc = TriangleDocument({{{"mesh", 0}}});
  doc["accessors"][0]["byteOffset"] = 9007199254740992;  // 2^53
  CHECK_THAT(Refusal(doc), HasSubstring("run past the bufferView"));
  doc = TriangleDocument({{{"mesh", 0}}});
  doc["buffers"][0]["byteLength"] = 45;
  CHECK_THAT(Refusal(doc), HasSubstring("buffers[0].byteLength: says 45 bytes, but the data has 44"));
  doc = TriangleDocument({{{"mesh", 0}}});
  doc["accessors"][1]["count"] = 2;
  doc["accessors"][1]["bufferView"] = 0;
  doc["accessors"][1]["byteOffset"] = 12;  // the float 1.0's bytes as indices: 0, then 0x3F80
  CHECK_THAT(Refusal(doc),
             HasSubstring("meshes[0].primitives[0].indices: element 1 is vertex 16256, past the 3 vertices"));
  doc = TriangleDocument({{{"mesh", 0}}});
  doc["accessors"][0]["componentType"] = 5123;
  CHECK_THAT(Refusal(doc), HasSubstring("POSITION: accessor 0 is VEC3 of component type 5123"));
  doc = TriangleDocument({{{"mesh", 7}}});
  CHECK_THAT(Refusal(doc), HasSubstring("nodes[0].mesh: expected an integer in 0..0, found 7"));
}

TEST_CASE(
    "glTF: a small file cannot make the models large: accessors of zeros, and one accessor read by many primitives") {
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["accessors"].push_back({{"componentType", 5126}, {"count", 1048577}, {"type", "VEC3"}});
  CHECK_THAT(Refusal(doc),
             HasSubstring("accessors[2]: an accessor of zeros (no bufferView) with more than 1048576 elements"));
  doc["accessors"][2]["count"] = 1048576;
  Json primitives = Json::array();
  for (int i = 0; i < 8; ++i) primitives.push_back({{"attributes", {{"POSITION", 2}}}});
  doc["meshes"][0]["primitives"] = primitives;
  CHECK_THAT(Refusal(doc), HasSubstring("accessor elements from 44 bytes of buffers: out of proportion, refused"));
}

TEST_CASE("glTF: a URI may be data: or a path inside the model's folder, nothing else") {
  const test::TempDir dir;
  const std::vector<std::uint8_t> bytes = TriangleBytes();
  test::WriteFile(dir / "tri.bin", std::string(bytes.begin(), bytes.end()));
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["buffers"][0]["uri"] = "tri.bin";
  CHECK(GltfScene(Parse(doc, dir.path()), {}, "t").models.size() == 1);
  doc["buffers"][0]["uri"] = "tr%69.bin";  // percent-encoded "i"
  CHECK(GltfScene(Parse(doc, dir.path()), {}, "t").models.size() == 1);
  for (const auto& [uri, why] : std::vector<std::pair<std::string, std::string>>{
           {"../tri.bin", "leaves the model's folder"},
           {"sub/%2e%2e/../x.bin", "leaves the model's folder"},
           {"/etc/passwd", "it is absolute"},
           {"file:///etc/passwd", "it has a scheme"},
           {"https://example.com/tri.bin", "it has a scheme"},
           {"a\\b.bin", "backslash"},
           {"data:application/octet-stream,abc", "not base64"},
           {"data:application/octet-stream;base64,A", "truncated"},
           {"data:application/octet-stream;base64,AB$=", "invalid character"},
       }) {
    doc["buffers"][0]["uri"] = uri;
    try {
      Parse(doc, dir.path());
      FAIL("accepted " << uri);
    } catch (const SceneError& e) {
      CHECK(e.where() == "buffers[0].uri");
      CHECK_THAT(e.problem(), HasSubstring(why));
    }
  }
}

TEST_CASE("glTF: .glb containers, glTF 1.0 and unknown required extensions") {
  const std::vector<std::uint8_t> bin = TriangleBytes();
  Json doc = TriangleDocument({{{"mesh", 0}}});
  doc["buffers"][0].erase("uri");
  const std::string json = doc.dump();
  const std::vector<std::uint8_t> glb = test::Glb(json, bin);
  CHECK(GltfScene(ParseGltf(glb, "t.glb", {}), {}, "t").models[0].vertices[1] == glm::dvec3(1, 0, 0));

  std::vector<std::uint8_t> cut(glb.begin(), glb.end() - 4);
  try {
    ParseGltf(cut, "t.glb", {});
    FAIL("a cut .glb was read");
  } catch (const SceneError& e) {
    CHECK(e.where() == "byte 8");
  }
  std::vector<std::uint8_t> long_chunk = glb;
  const std::size_t bin_header = 12 + 8 + (json.size() + 3) / 4 * 4;  // after the padded JSON chunk
  long_chunk[bin_header] = 0xff;                                      // the BIN chunk's length, far past the end
  long_chunk[bin_header + 3] = 0x7f;
  try {
    ParseGltf(long_chunk, "t.glb", {});
    FAIL("a chunk past the end was read");
  } catch (const SceneError& e) {
    CHECK_THAT(e.problem(), HasSubstring("runs past the end of the file"));
  }

  Json old = TriangleDocument({{{"mesh", 0}}});
  old["asset"]["version"] = "1.0";
  CHECK_THAT(Refusal(old), HasSubstring("asset.version: glTF \"1.0\": twinraster reads glTF 2.0 only"));
  Json required = TriangleDocument({{{"mesh", 0}}});
  required["extensionsRequired"] = {"KHR_materials_unlit", "KHR_draco_mesh_compression"};
  CHECK_THAT(Refusal(required),
             HasSubstring("extensionsRequired[1]: the file requires the extension KHR_draco_mesh_compression"));
}

TEST_CASE("A chosen canvas size resizes any scene's canvas and widens its viewport to the same shape") {
  Scene scene;
  scene.canvas = Canvas{600, 600};
  scene.viewport = Viewport{1, 1, 1};
  ResizeCanvas(scene, CanvasSize{1200, 600});
  CHECK(scene.canvas.width == 1200);
  CHECK(scene.viewport.width == 2);
  CHECK(scene.viewport.height == 1);
  ResizeCanvas(scene, CanvasSize{100, 400});
  CHECK(scene.viewport.width == 2);
  CHECK(scene.viewport.height == 8);
}
