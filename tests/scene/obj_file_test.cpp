// OBJ files as twinraster reads them: every face format, negative indices, fans in file order,
// usemtl groups; and every bad file one SceneError naming the file, the line and the problem.
#include "scene/obj_file.hpp"

#include "scene/scene_error.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <glm/geometric.hpp>

#include <array>
#include <cstdint>
#include <iterator>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

using Corners = std::array<std::uint32_t, 3>;
constexpr std::uint32_t N = kNoNormal;

// The SceneError ParseObj throws for `text`, which must be bad.
SceneError ObjError(const std::string& text) {
  try {
    (void)ParseObj(text, "mesh.obj");
  } catch (const SceneError& e) {
    return e;
  }
  throw std::runtime_error("no error for:\n" + text);
}

const std::string kThreeVertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\n";

}  // namespace

TEST_CASE("OBJ faces in every format: v, v/vt, v//vn and v/vt/vn", "[scene][obj]") {
  const ObjMesh mesh = ParseObj(kThreeVertices +
                                    "vt 0 0\nvt 1 0\nvt 0 1\n"
                                    "vn 0 0 1\nvn 0 0 -1\n"
                                    "f 1 2 3\n"
                                    "f 1/1 2/2 3/3\n"
                                    "f 1//2 2//2 3//1\n"
                                    "f 3/3/1 2/2/2 1/1/1\n",
                                "mesh.obj");
  REQUIRE(mesh.vertices == std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  REQUIRE(mesh.normals == std::vector<glm::dvec3>{{0, 0, 1}, {0, 0, -1}});
  REQUIRE(mesh.triangles == std::vector<Corners>{{0, 1, 2}, {0, 1, 2}, {0, 1, 2}, {2, 1, 0}});
  REQUIRE(mesh.triangle_normals == std::vector<Corners>{{N, N, N}, {N, N, N}, {1, 1, 0}, {0, 1, 0}});
  REQUIRE(mesh.triangle_materials == std::vector<std::uint32_t>(4, kNoMaterial));
  REQUIRE(mesh.materials.empty());
}

TEST_CASE("OBJ without any vn: no per-corner normals at all", "[scene][obj]") {
  const ObjMesh mesh = ParseObj(kThreeVertices + "vn 0 0 1\nf 1 2 3\n", "mesh.obj");
  REQUIRE(mesh.triangles.size() == 1);
  REQUIRE(mesh.normals.size() == 1);  // written, but no face names it
  REQUIRE(mesh.triangle_normals.empty());
}

TEST_CASE("OBJ negative indices count back from the last v (or vn) before their line", "[scene][obj]") {
  const ObjMesh mesh = ParseObj(kThreeVertices +
                                    "vn 1 0 0\n"
                                    "f -3 -2 -1\n"
                                    "v 5 5 5\nv 6 6 6\n"
                                    "vn 0 1 0\n"
                                    "f -1//-1 -2//-2 -5//-1\n",
                                "mesh.obj");
  REQUIRE(mesh.triangles == std::vector<Corners>{{0, 1, 2}, {4, 3, 0}});
  REQUIRE(mesh.triangle_normals == std::vector<Corners>{{N, N, N}, {1, 0, 1}});
}

TEST_CASE("OBJ polygons are fans in file order: a quad and a pentagon", "[scene][obj]") {
  // The quad's diagonal v0-v2 is the longer one, so tinyobjloader's own triangulation (along the
  // shorter diagonal) would give (0, 1, 3), (1, 2, 3) instead.
  const ObjMesh mesh = ParseObj(
      "v 0 0 0\nv 1 -0.2 0\nv 4 0 0\nv 1 0.2 0\nv 2 2 0\n"
      "f 1 2 3 4\n"
      "f 5 1 4 2 3\n",
      "mesh.obj");
  REQUIRE(mesh.triangles == std::vector<Corners>{{0, 1, 2}, {0, 2, 3}, {4, 0, 3}, {4, 3, 1}, {4, 1, 2}});
  // Normals follow their corners through the fan.
  const ObjMesh lit = ParseObj(
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nvn 0 0 2\nvn 0 0 3\nvn 0 0 4\n"
      "f 1//1 2//2 3//3 4//4\n",
      "mesh.obj");
  REQUIRE(lit.triangle_normals == std::vector<Corners>{{0, 1, 2}, {0, 2, 3}});
}

TEST_CASE("OBJ usemtl groups: materials in order of first use, faces before any usemtl have none", "[scene][obj]") {
  const ObjMesh mesh = ParseObj(kThreeVertices +
                                    "mtllib never-read.mtl\n"
                                    "f 1 2 3\n"
                                    "usemtl   skin  \n"
                                    "f 1 2 3 1\n"
                                    "usemtl eyes\n"
                                    "f 3 2 1\n"
                                    "usemtl skin\n"
                                    "f 2 3 1\n",
                                "mesh.obj");
  REQUIRE(mesh.materials == std::vector<std::string>{"skin", "eyes"});
  REQUIRE(mesh.triangle_materials == std::vector<std::uint32_t>{kNoMaterial, 0, 0, 1, 0});
}

TEST_CASE("OBJ lines: CRLF, CR and LF endings, blank and comment lines, statements twinraster ignores",
          "[scene][obj]") {
  const ObjMesh mesh = ParseObj(
      "# a comment\r\n"
      "o thing\r"
      "g part one\n"
      "s 1\n"
      "\n"
      "  \t\n"
      "v 0.1 -2 1e3 1\r\n"  // w, ignored
      "\tv   +1.5\t.5 -0 \n"
      "v 0 1 0 0.5 0.5 0.5\n"  // r g b, ignored
      "vp 0.5\n"
      "l 1 2\n"
      "f 1 2 4\n"  // a positive index may name a vertex written further on
      "v 9 9 9",   // no final line break
      "mesh.obj");
  REQUIRE(mesh.vertices.size() == 4);
  REQUIRE(mesh.vertices[0] == glm::dvec3(0.1, -2, 1000));  // in double: 0.1 is the double nearest 0.1
  REQUIRE(mesh.vertices[1] == glm::dvec3(1.5, 0.5, 0));
  REQUIRE(mesh.vertices[3] == glm::dvec3(9, 9, 9));
  REQUIRE(mesh.triangles == std::vector<Corners>{{0, 1, 3}});
}

TEST_CASE("Bad OBJ files: one SceneError naming the file, the line and the problem", "[scene][obj][bad-input]") {
  struct Case {
    const char* what;
    std::string text;
    std::string where;
    std::string problem;
  };
  const std::vector<Case> cases = {
      {"vertex index past the end", kThreeVertices + "f 1 2 4\n", "line 4",
       "f: corner 3 \"4\": vertex index 4 is out of range: the file has 3 vertices (v lines)"},
      {"negative vertex index reaching back too far", "v 0 0 0\nf -1 -1 -2\nv 1 1 1\nv 2 2 2\n", "line 2",
       "f: corner 3 \"-2\": vertex index -2 is out of range: only 1 vertex (v line) comes before this line"},
      {"negative index before any vertex", "f -1 -1 -1\nv 1 1 1\n", "line 1",
       "vertex index -1 is out of range: no vertices (v lines) come before this line"},
      {"normal index past the end", kThreeVertices + "vn 0 0 1\nf 1//1 2//2 3//1\n", "line 5",
       "f: corner 2 \"2//2\": normal index 2 is out of range: the file has 1 normal (vn line)"},
      {"texture coordinate index without vt", kThreeVertices + "f 1/5 2/5 3/5\n", "line 4",
       "texture coordinate index 5 is out of range: the file has no texture coordinates (vt lines)"},
      {"index 0", kThreeVertices + "f 0 1 2\n", "line 4", "vertex index 0: indices count from 1 (or back from -1)"},
      {"normal index 0", kThreeVertices + "vn 0 0 1\nf 1//0 2//1 3//1\n", "line 5",
       "normal index 0: indices count from 1"},
      {"index beyond any integer", kThreeVertices + "f 1 2 99999999999999999999999\n", "line 4",
       "vertex index 99999999999999999999999 is out of range"},
      {"malformed number", "v 0 0 0\nv 1 2.5x 3\n", "line 2", "v: \"2.5x\" is not a number"},
      {"malformed normal", kThreeVertices + "vn 0 0 one\nf 1 2 3\n", "line 4", "vn: \"one\" is not a number"},
      {"malformed texture coordinate", kThreeVertices + "vt 0.5 .\nf 1 2 3\n", "line 4", "vt: \".\" is not a number"},
      {"number with an empty exponent", "v 1e 0 0\n", "line 1", "v: \"1e\" is not a number"},
      {"not a finite number", "v nan 0 0\n", "line 1", "v: \"nan\" is not a finite number"},
      {"number beyond double", "v 1e999 0 0\n", "line 1", "v: number 1e999 is out of range for a double"},
      {"absurd number", "v 0 0 0\n\nv 0 -2e12 0\n", "line 3", "v: number -2e12 is absurd (magnitude above 1e+12)"},
      {"too few coordinates", "v 1 2\n", "line 1",
       "v: expected x y z (optionally followed by w, or by r g b), found 2 numbers"},
      {"v alone", "v\n", "line 1", "found none"},
      {"five numbers", "v 1 2 3 4 5\n", "line 1", "found 5 numbers"},
      {"normal with two numbers", "vn 0 1\n", "line 1", "vn: expected x y z, found 2 numbers"},
      {"a comment after a statement", "v 1 2 3 # top\n", "line 1",
       "\"#\" is not a number (a comment must be on a line of its own)"},
      {"face with two corners", kThreeVertices + "f 1 2\n", "line 4", "f: a face needs at least 3 corners, found 2"},
      {"face with no corners", kThreeVertices + "f\n", "line 4", "found none"},
      {"corner with four parts", kThreeVertices + "f 1/1/1/1 2 3\n", "line 4",
       "f: corner 1 \"1/1/1/1\" is not v, v/vt, v//vn or v/vt/vn"},
      {"corner with an empty vt", kThreeVertices + "f 1/ 2 3\n", "line 4",
       "corner 1 \"1/\" is not v, v/vt, v//vn or v/vt/vn"},
      {"corner without a vertex", kThreeVertices + "f /1 2 3\n", "line 4", "corner 1 \"/1\" is not v"},
      {"corner that is not a number", kThreeVertices + "f 1 2 three\n", "line 4",
       "f: corner 3 \"three\": \"three\" is not an index (an integer)"},
      {"fractional index", kThreeVertices + "f 1 2 3.0\n", "line 4", "\"3.0\" is not an index"},
      {"no faces", kThreeVertices + "# nothing else\n", "(file)", "no faces (f lines): nothing to draw"},
      {"empty file", "", "(file)", "no faces"},
      {"a NUL byte", kThreeVertices + std::string("f 1 2 3\0", 8) + "\n", "line 4",
       "not an OBJ text file: binary data (a NUL byte)"},
      {"line numbers across CRLF and a lone CR", "v 0 0 0\r\nv 1 0 0\rv 0 1 0\r\n\r\nf 1 2 9\r\n", "line 5",
       "vertex index 9 is out of range"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const SceneError e = ObjError(c.text);
    INFO(e.what());
    REQUIRE(e.file() == "mesh.obj");
    REQUIRE(e.where() == c.where);
    REQUIRE(e.problem().find(c.problem) != std::string::npos);
    REQUIRE(std::string(e.what()).find('\n') == std::string::npos);  // one line
  }
}

TEST_CASE("OBJ files that cannot be read: missing, a directory, a device", "[scene][obj][bad-input]") {
  const test::TempDir dir;
  const std::vector<std::pair<std::filesystem::path, std::string>> cases = {
      {dir / "none.obj", "no such file"},
      {dir.path(), "is a directory, not an OBJ file"},
      {"/dev/zero", "not a regular file"},
  };
  for (const auto& [path, problem] : cases) {
    INFO(path);
    try {
      (void)ReadObjFile(path);
      FAIL("no error");
    } catch (const SceneError& e) {
      REQUIRE(e.file() == path.string());
      REQUIRE(e.where() == "(file)");
      REQUIRE(e.problem() == problem);
    }
  }
  // A file's own problems name it as it was opened.
  test::WriteFile(dir / "bad.obj", "v 0 0 0\nf 1 1 2\n");
  try {
    (void)ReadObjFile(dir / "bad.obj");
    FAIL("no error");
  } catch (const SceneError& e) {
    REQUIRE(e.file() == (dir / "bad.obj").string());
    REQUIRE(e.where() == "line 2");
  }
}

TEST_CASE("ObjModel colours each triangle by its material, or in the model's colour", "[scene][obj]") {
  const std::string text = kThreeVertices + "f 1 2 3\nusemtl skin\nf 1 2 3\nusemtl eyes\nf 1 2 3\n";
  const Rgb8 grey{9, 9, 9}, skin{200, 150, 120};
  const Model model = ObjModel(ParseObj(text, "mesh.obj"), "head", grey, {{"skin", skin}});
  REQUIRE(model.name == "head");
  REQUIRE(model.vertices.size() == 3);
  REQUIRE(model.triangles.size() == 3);
  REQUIRE(model.triangles[0].colour == grey);  // before any usemtl
  REQUIRE(model.triangles[1].colour == skin);
  REQUIRE(model.triangles[2].colour == grey);  // "eyes" has no entry
  REQUIRE(model.shading == Shading::kUnlit);
  REQUIRE(model.triangle_normals.empty());
}

namespace {

// Random OBJ text: valid files whose mesh the generator knows, and the same files with one line
// broken. Both readers (the line check and tinyobjloader) must agree on every one of them.
struct RandomObj {
  std::string text;
  std::vector<glm::dvec3> vertices;
  std::vector<Corners> triangles, triangle_normals;
  bool broken = false;
};

RandomObj MakeRandomObj(std::mt19937& rng) {
  const auto pick = [&](std::size_t n) { return std::uniform_int_distribution<std::size_t>(0, n - 1)(rng); };
  const char* const endings[] = {"\n", "\r\n", "\r"};
  const char* const blanks[] = {" ", "\t", "  ", " \t"};
  const std::string ending = endings[pick(3)];
  RandomObj obj;
  std::size_t normals = 0;
  std::vector<std::string> lines;
  const std::size_t count = 5 + pick(40);
  bool any_normal = false;
  for (std::size_t l = 0; l < count; ++l) {
    const std::string blank = blanks[pick(4)];
    const std::size_t kind = pick(10);
    if (kind < 4 || obj.vertices.size() < 3) {
      glm::dvec3 v;
      std::string line = "v";
      for (int k = 0; k < 3; ++k) {
        v[k] = static_cast<double>(static_cast<int>(pick(401)) - 200) / 8;  // short decimals: 12.625
        line += blank + std::to_string(v[k]).substr(0, std::to_string(v[k]).find('.') + 4);
      }
      obj.vertices.push_back(v);
      lines.push_back(line);
    } else if (kind == 4) {
      lines.push_back("vn 0 0 1");
      ++normals;
    } else if (kind == 5) {
      lines.push_back(pick(2) ? "# comment" : pick(2) ? "usemtl m" + std::to_string(pick(3)) : "g group");
    } else {
      const std::size_t corners = 3 + pick(4);
      const bool with_normals = normals > 0 && pick(2);
      std::string line = "f";
      std::vector<std::uint32_t> vs, ns;
      for (std::size_t c = 0; c < corners; ++c) {
        const std::size_t v = pick(obj.vertices.size());
        const bool negative = pick(2);
        line += blank + (negative ? "-" + std::to_string(obj.vertices.size() - v) : std::to_string(v + 1));
        vs.push_back(static_cast<std::uint32_t>(v));
        if (with_normals) {
          const std::size_t n = pick(normals);
          line += "//" + std::to_string(n + 1);
          ns.push_back(static_cast<std::uint32_t>(n));
        } else {
          ns.push_back(N);
        }
      }
      any_normal = any_normal || with_normals;
      for (std::size_t k = 1; k + 1 < corners; ++k) {
        obj.triangles.push_back({vs[0], vs[k], vs[k + 1]});
        obj.triangle_normals.push_back({ns[0], ns[k], ns[k + 1]});
      }
      lines.push_back(line);
    }
  }
  if (obj.triangles.empty()) {
    lines.push_back("f 1 2 3");
    obj.triangles.push_back({0, 1, 2});
    obj.triangle_normals.push_back({N, N, N});
  }
  if (!any_normal) obj.triangle_normals.clear();
  if (pick(2)) {
    // One line replaced by something likely wrong (or, now and then, harmless).
    const char* const junk[] = {"v 1 2",      "v 1 2 x",   "f 1 2",       "f 0 1 2",     "f 1/2/3/4 1 1",
                                "vn 1 1",     "f 1 2 999", "f -999 1 2",  "v 1e999 0 0", "vt",
                                "f 1//7 1 1", "f a b c",   "v 1 2 3 # c", "o fine"};
    lines[pick(lines.size())] = junk[pick(std::size(junk))];
    obj.broken = true;
  }
  for (const std::string& line : lines) obj.text += line + ending;
  return obj;
}

}  // namespace

TEST_CASE("Random OBJ text: the mesh the file describes, or a SceneError, never a disagreement", "[scene][obj]") {
  std::mt19937 rng(20261123);
  std::size_t read = 0, refused = 0;
  for (int i = 0; i < 3000; ++i) {
    const RandomObj obj = MakeRandomObj(rng);
    INFO(obj.text);
    try {
      const ObjMesh mesh = ParseObj(obj.text, "random.obj");
      ++read;
      if (obj.broken) continue;  // a harmless replacement: only the invariants below hold
      REQUIRE(mesh.vertices.size() == obj.vertices.size());
      for (std::size_t v = 0; v < mesh.vertices.size(); ++v)
        REQUIRE(glm::length(mesh.vertices[v] - obj.vertices[v]) < 1e-12);
      REQUIRE(mesh.triangles == obj.triangles);
      REQUIRE(mesh.triangle_normals == obj.triangle_normals);
    } catch (const SceneError& e) {
      INFO(e.what());
      REQUIRE(obj.broken);
      REQUIRE(e.file() == "random.obj");
      REQUIRE((e.where().rfind("line ", 0) == 0 || e.problem().rfind("no faces", 0) == 0));
      ++refused;
    }
  }
  REQUIRE(read > 1000);
  REQUIRE(refused > 1000);
}
