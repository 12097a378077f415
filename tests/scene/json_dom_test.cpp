// Writes every field of every scene the scene library loads, doubles as their bits, and every
// refusal's message, to scene-dump-<DOM>.txt: built once on each JSON DOM (simdjson, nlohmann),
// so that a CTest compares the two dumps byte for byte. The inputs: every scene, glTF and OBJ file
// under scenes/, numbers at the edges of double, and the hostile texts below, each read as a scene
// file and as a glTF file.
#include "scene/gltf_document.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <algorithm>
#include <bit>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

// One line per field; a double as its 16 hex digits, so that -0 and the last bit show.
class Dump {
 public:
  void D(double x) { text_ << ' ' << std::hex << std::bit_cast<std::uint64_t>(x) << std::dec; }
  void V(const glm::dvec3& v) { D(v.x), D(v.y), D(v.z); }
  void M(const glm::dmat3& m) {
    for (int c = 0; c < 3; ++c) V(m[c]);
  }
  void M(const glm::dmat4& m) {
    for (int c = 0; c < 4; ++c) D(m[c].x), D(m[c].y), D(m[c].z), D(m[c].w);
  }
  void C(const Rgb8& c) { text_ << ' ' << int{c.r} << ',' << int{c.g} << ',' << int{c.b}; }
  template <class T>
  Dump& operator<<(const T& t) {
    text_ << t;
    return *this;
  }
  std::string str() const { return text_.str(); }

 private:
  std::ostringstream text_;
};

void DumpModel(Dump& d, const Model& m) {
  d << "model " << m.name << " shading " << static_cast<int>(m.shading) << " source " << m.source << "\n";
  for (const glm::dvec3& v : m.vertices) d << " v", d.V(v), d << "\n";
  for (const Triangle& t : m.triangles)
    d << " t " << t.v[0] << ' ' << t.v[1] << ' ' << t.v[2], d.C(t.colour), d << "\n";
  for (const glm::dvec3& n : m.normals) d << " n", d.V(n), d << "\n";
  for (const auto& tn : m.triangle_normals) d << " tn " << tn[0] << ' ' << tn[1] << ' ' << tn[2] << "\n";
  for (const Rgb8& c : m.vertex_colours) d << " vc", d.C(c), d << "\n";
}

void DumpInstance(Dump& d, const Instance& i) {
  d << "instance " << i.model << " s", d.V(i.transform.scale), d << " r", d.M(i.transform.rotation);
  d << " t", d.V(i.transform.translation), d << "\n";
  if (!i.transform.steps) return;
  for (const TransformStep& s : *i.transform.steps) {
    d << " step " << static_cast<int>(s.kind) << ' ' << s.label, d.V(s.vector), d.M(s.rotation), d.M(s.matrix);
    d << "\n";
  }
}

std::string DumpScene(const Scene& s) {
  Dump d;
  d << "scene " << s.name << " canvas " << s.canvas.width << 'x' << s.canvas.height, d.C(s.canvas.background);
  d << "\nviewport", d.D(s.viewport.width), d.D(s.viewport.height), d.D(s.viewport.distance);
  d << ' ' << static_cast<int>(s.viewport.projection) << "\ndepth", d.D(s.depth.near), d.D(s.depth.far);
  d << ' ' << s.depth.reversed << "\ncamera", d.V(s.camera.position), d.M(s.camera.rotation);
  d << "\nwireframe " << s.wireframe << "\n";
  for (const Model& m : s.models) DumpModel(d, m);
  for (const Instance& i : s.instances) DumpInstance(d, i);
  for (const InstanceGrid& g : s.grids) {
    d << "grid " << g.written << ' ' << g.first << ' ' << g.count[0] << ' ' << g.count[1] << ' ' << g.count[2];
    d.V(g.spacing), d << "\n";
  }
  if (s.lighting) {
    d << "ambient", d.D(s.lighting->ambient), d << "\n";
    for (const Light& l : s.lighting->lights)
      d << "light " << static_cast<int>(l.kind), d.V(l.vector), d.D(l.intensity), d << "\n";
  }
  for (const std::string& note : s.notes) d << "note " << note << "\n";
  return d.str();
}

struct Outcome {
  bool loaded;
  std::string text;
};

Outcome Load(const std::function<Scene()>& load) {
  try {
    return {true, DumpScene(load())};
  } catch (const SceneError& e) {
    return {false, std::string("refused: ") + e.what() + "\n"};
  }
}

std::vector<std::uint8_t> Bytes(const std::string& text) { return {text.begin(), text.end()}; }

std::string ReadText(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// A small scene with `value` written where the first instance's translation's x is.
std::string SceneWith(const std::string& value) {
  return R"({"canvas": {"width": 8, "height": 8}, "viewport": {"width": 1, "height": 1, "distance": 1},
  "camera": {"position": [0, 0, 0], "rotation": {"axis": "y", "degrees": 0}},
  "models": {"m": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2, "red"]]}},
  "instances": [{"model": "m", "transform": {"translation": [)" +
         value + R"(, 0, 5]}}]})";
}

// Numbers each DOM must read to the same double, or refuse with the same message.
std::vector<std::string> Numbers() {
  return {"-0",
          "-0.0",
          "0e0",
          "-0e-5",
          "1e-400",
          "-1e-400",
          "4.9e-324",
          "2.4703282292062328e-324",
          "2.2250738585072011e-308",
          "0.1",
          "0.30000000000000004",
          "1e12",
          "999999999999.99994",
          "9007199254740993",
          "-9007199254740993",
          "18446744073709551615",
          "18446744073709551616",
          "9223372036854775807",
          "-9223372036854775808",
          "-9223372036854775809",
          "123456789012345678901234567890",
          "1e400",
          "-1e400",
          "1.7976931348623157e308",
          "1.7976931348623159e308",
          "1E2",
          "1e+2",
          "12345.678901234567890123",
          "0.000001",
          "3.141592653589793238462643"};
}

// Texts that are not good scenes: each must be refused, the same way by both DOMs.
std::vector<std::string> HostileScenes() {
  const std::string deep = std::string(100, '[') + std::string(100, ']');
  return {"",
          "\xEF\xBB\xBF",
          "\xEF\xBB\xBF{\"canvas\": {\"width\": 600,, \"height\": 600}}",
          "{\n  \"canvas\": {\"width\": 600,, \"height\": 600}\n}",
          "{\n  \"canvas\": {",
          "{\"canvas\": {\"width\": 1e999}}",
          "{\"instances\": [0, -1e999]}",
          "{\"canvas\": {\"width\": 600, \"height\": 600, \"width\": 800}}",
          "{\"comment\": " + deep + "}",
          "{\"comment\": [1, 2], \"comment\": " + deep + "}",
          std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16),
          std::string("{\n  \"canvas\"\0: 1}", 17),
          "[1, 2, 3]",
          "{\"canvs\": {}, \"viewprt\": {}}",
          "{\"comment\": \"\\udc00\"}",
          "{\"comment\": \"\\ud800x\"}",
          "{\"comment\": \"\xC0\xAF\"}",
          "{\"comment\": \"\xED\xA0\x80\"}",
          "{\"comment\": 01}",
          "{\"comment\": 1.}",
          "{\"comment\": \"a\tb\"}",
          "{\"comment\": 123456789012345678901234567890, \"x\": }",
          "{} {}",
          SceneWith("1e13"),
          SceneWith("\"1\"")};
}

// The first glTF file of scenes/gltf with `insert` written right after its opening brace.
std::vector<std::string> HostileGltf(const std::string& gltf) {
  const auto with = [&](const std::string& insert) {
    std::string text = gltf;
    return text.insert(text.find('{') + 1, insert);
  };
  const auto nested = [](std::size_t depth) { return std::string(depth, '[') + std::string(depth, ']'); };
  return {with("\"asset\": {\"version\": \"1.0\"},"),
          with("\"extras\": 1, \"extras\": 2,"),
          with("\"extras\": " + nested(62) + ","),
          with("\"extras\": " + nested(63) + ","),
          with("\"extras\": " + nested(64) + ","),
          with("\"extras\": " + nested(1022) + ","),
          with("\"extras\": " + nested(1023) + ","),
          with("\"extras\": " + nested(1024) + ","),
          with("\"extras\": " + nested(1025) + ","),
          with("\"extras\": {\"a\": 1, \"a\": 2}, \"x\": " + nested(1100) + ","),
          with("\"extras\": {\"a\": 1, \"a\": 2}, \"x\": [1,,2],"),
          with("\"extras\": [1,,2], \"y\": {\"a\": 1, \"a\": 2},"),
          with("\"extras\": 18446744073709551616,"),
          with("\"extras\": {\"a\": 1, \"a\": 2}, \"b\": 1e400,"),
          "\xEF\xBB\xBF" + gltf,
          with("\"extras\": \"\\udc00\","),
          with("\"extras\": -0,"),
          gltf + " x"};
}

}  // namespace

TEST_CASE("Every scene and every hostile text as the scene library reads them on " TWINRASTER_DUMP_DOM
          ": dumped for the comparison",
          "[json-dom]") {
  const std::filesystem::path source = test::SourcePath("");
  const std::filesystem::path out = std::string("scene-dump-") + TWINRASTER_DUMP_DOM + ".txt";
  std::filesystem::remove(out);
  std::vector<std::filesystem::path> files;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(source / "scenes")) {
    const std::string ext = entry.path().extension().string();
    if (ext == ".json" || ext == ".gltf" || ext == ".glb" || ext == ".obj") files.push_back(entry.path());
  }
  std::sort(files.begin(), files.end());
  std::string dump, first_gltf;
  std::size_t loaded = 0, hostile_loaded = 0;
  for (const std::filesystem::path& file : files) {
    const Outcome o = Load([&] { return LoadSceneOrObj(file); });
    loaded += o.loaded;
    dump += "== " + std::filesystem::relative(file, source).string() + "\n" + o.text;
    if (first_gltf.empty() && file.extension() == ".gltf") first_gltf = ReadText(file);
  }
  for (const std::string& number : Numbers()) {
    dump += "== number " + number + "\n" + Load([&] { return ParseScene(SceneWith(number), "n.json"); }).text;
  }
  const auto hostile = [&](const std::string& what, const std::function<Scene()>& load) {
    const Outcome o = Load(load);
    hostile_loaded += o.loaded;
    dump += "== hostile " + what + "\n" + o.text;
  };
  for (const std::string& text : HostileScenes()) {
    const std::string size = std::to_string(text.size()) + " bytes";
    hostile("scene of " + size, [&] { return ParseScene(text, "h.json"); });
    hostile("glTF of " + size, [&] { return GltfScene(ParseGltf(Bytes(text), "h.gltf", {}), {}, "h"); });
  }
  REQUIRE(!first_gltf.empty());
  for (const std::string& text : HostileGltf(first_gltf)) {
    const Outcome o =
        Load([&] { return GltfScene(ParseGltf(Bytes(text), "h.gltf", source / "scenes/gltf"), {}, "h"); });
    dump += "== glTF variant of " + std::to_string(text.size()) + " bytes\n" + o.text;
  }
  std::ofstream(out, std::ios::binary) << dump;
  INFO(files.size() << " files");
  CHECK(loaded >= 20);
  CHECK(hostile_loaded == 0);
}
