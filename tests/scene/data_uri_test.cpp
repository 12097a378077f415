// A scene file can carry its models inline: "obj" and "gltf" as data: URIs (RFC 2397, base64 or
// percent-encoded) load to exactly the Scene the same scene naming the files loads, field by field
// and bit for bit (the model's source aside, which says where it came from); bad URIs are refused
// naming the file and the JSON path.
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/gltf_bytes.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <cctype>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

// A lit scene with one model read from `key` ("obj" or "gltf") written as `value`, drawn twice.
std::string SceneWith(const std::string& key, const std::string& value) {
  const nlohmann::ordered_json scene = {
      {"canvas", {{"width", 64}, {"height", 64}}},
      {"viewport", {{"width", 1}, {"height", 1}, {"distance", 1}}},
      {"camera", {{"position", {0, 0, -4}}, {"rotation", {{"axis", "y"}, {"degrees", 0}}}}},
      {"lighting",
       {{"ambient", 0.2}, {"lights", {{{"type", "directional"}, {"direction", {1, 1, -1}}, {"intensity", 0.8}}}}}},
      {"models", {{"m", {{key, value}}}}},
      {"instances", {{{"model", "m"}}, {{"model", "m"}, {"transform", {{"scale", 0.5}, {"translation", {1, 0, 0}}}}}}}};
  return scene.dump(1);
}

std::vector<std::uint8_t> FileBytes(const std::string& relative) {
  const std::string text = test::ReadFile(test::SourcePath(relative));
  return {text.begin(), text.end()};
}

// Every character but the unreserved ones percent-encoded.
std::string PercentEncoded(const std::vector<std::uint8_t>& bytes) {
  std::string out;
  for (const std::uint8_t b : bytes) {
    if (std::isalnum(b) || b == '-' || b == '.' || b == '_' || b == '~') {
      out += static_cast<char>(b);
    } else {
      char hex[4];
      std::snprintf(hex, sizeof hex, "%%%02X", static_cast<unsigned>(b));
      out += hex;
    }
  }
  return out;
}

template <class T>
bool SameBits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

void RequireSameScene(const Scene& a, const Scene& b) {
  REQUIRE(a.models.size() == b.models.size());
  for (std::size_t m = 0; m < a.models.size(); ++m) {
    const Model &x = a.models[m], &y = b.models[m];
    CHECK(x.name == y.name);
    CHECK(SameBits(x.vertices, y.vertices));
    REQUIRE(x.triangles.size() == y.triangles.size());
    for (std::size_t t = 0; t < x.triangles.size(); ++t) {
      CHECK(x.triangles[t].v == y.triangles[t].v);
      CHECK(x.triangles[t].colour == y.triangles[t].colour);
    }
    CHECK(SameBits(x.normals, y.normals));
    CHECK(x.triangle_normals == y.triangle_normals);
    CHECK(x.shading == y.shading);
    CHECK(x.vertex_colours == y.vertex_colours);
  }
  REQUIRE(a.instances.size() == b.instances.size());
  for (std::size_t i = 0; i < a.instances.size(); ++i) {
    const Transform &x = a.instances[i].transform, &y = b.instances[i].transform;
    CHECK(a.instances[i].model == b.instances[i].model);
    CHECK(std::memcmp(&x.scale, &y.scale, sizeof x.scale) == 0);
    CHECK(std::memcmp(&x.rotation, &y.rotation, sizeof x.rotation) == 0);
    CHECK(std::memcmp(&x.translation, &y.translation, sizeof x.translation) == 0);
    CHECK((x.steps == nullptr) == (y.steps == nullptr));
  }
  CHECK(a.notes == b.notes);
  CHECK(a.lighting.has_value() == b.lighting.has_value());
}

std::string Refusal(const std::string& key, const std::string& value) {
  try {
    ParseScene(SceneWith(key, value), "inline.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(no error)";
}

}  // namespace

TEST_CASE("Every OBJ mesh carried as a data: URI loads to the Scene its file gives", "[scene][data-uri]") {
  for (const char* name : {"gem.obj", "knot.obj", "sphere.obj", "terrain.obj", "torus.obj"}) {
    INFO(name);
    const std::filesystem::path meshes = test::SourcePath("scenes/meshes");
    const std::vector<std::uint8_t> bytes = FileBytes(std::string("scenes/meshes/") + name);
    const Scene named = ParseScene(SceneWith("obj", name), "named.json", meshes);
    REQUIRE(named.models.at(0).triangles.size() > 10);
    for (const std::string& uri : {"data:model/obj;base64," + test::Base64(bytes), "data:," + PercentEncoded(bytes),
                                   "data:text/plain;charset=utf-8," + PercentEncoded(bytes)}) {
      // No directory: a model carried inline needs no file.
      const Scene inline_scene = ParseScene(SceneWith("obj", uri), "inline.json");
      RequireSameScene(named, inline_scene);
      CHECK(inline_scene.models.at(0).source.rfind("data:", 0) == 0);
    }
  }
}

TEST_CASE("A glTF file carried as a data: URI loads to the model its file gives", "[scene][data-uri]") {
  for (const char* name : {"colonnade.glb", "strips.gltf"}) {
    INFO(name);
    const std::vector<std::uint8_t> bytes = FileBytes(std::string("scenes/gltf/") + name);
    const Scene named = ParseScene(SceneWith("gltf", name), "named.json", test::SourcePath("scenes/gltf"));
    const Scene inline_scene =
        ParseScene(SceneWith("gltf", "data:model/gltf-binary;base64," + test::Base64(bytes)), "inline.json");
    RequireSameScene(named, inline_scene);
  }
}

TEST_CASE("Bad data: URIs are refused naming the file and the JSON path", "[scene][data-uri]") {
  CHECK(Refusal("obj", "data:model/obj;base64,v 0 0 0@") ==
        "inline.json: models.m.obj: the data: URI's base64 has an invalid character at position 1");
  CHECK(Refusal("obj", "data:image/png;base64,AAAA") ==
        "inline.json: models.m.obj: a data: URI of media type \"image/png\"; use one of text/plain, model/obj, "
        "application/octet-stream (or none)");
  CHECK(Refusal("obj", "data:model/obj") == "inline.json: models.m.obj: a data: URI without a comma");
  CHECK(Refusal("obj", "data:,v%2") ==
        "inline.json: models.m.obj: the data: URI's '%' at character 8 is not followed by two hexadecimal digits");
  CHECK(Refusal("obj", "data:model/obj;base64,AAAAA") ==
        "inline.json: models.m.obj: the data: URI's base64 is truncated");
  // A problem inside the mesh names the line, in the model the scene file carries.
  const std::string bad_line = Refusal("obj", "data:,v%201%202%203%0Af%201%201%209%0A");
  INFO(bad_line);
  CHECK(bad_line.rfind("inline.json (models.m.obj, a data: URI): line 2: ", 0) == 0);
  CHECK(Refusal("gltf", "data:text/html,<p>") ==
        "inline.json: models.m.gltf: a data: URI of media type \"text/html\"; use one of model/gltf+json, "
        "model/gltf-binary, application/json, application/octet-stream (or none)");
}
