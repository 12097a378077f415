// Scenes with OBJ models and lighting: paths relative to the scene, colours and materials, the
// shading rules, every new error; and an OBJ file on its own framed by SceneForObj.
#include "scene/obj_scene.hpp"

#include "scene/obj_file.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

using namespace twinraster;

namespace {

// A triangle without normals, and a quad (two triangles) whose corners name normals.
const std::string kTriangleObj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
const std::string kQuadWithNormalsObj = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvn 0 0 1\nf 1//1 2//1 3//1 4//1\n";

// A scene around `models` (a JSON object) and `instances`; `lighting` is added when not null.
std::string SceneText(const nlohmann::json& models, const nlohmann::json& instances,
                      const nlohmann::json& lighting = nullptr) {
  nlohmann::json scene = {
      {"canvas", {{"width", 64}, {"height", 64}}},
      {"viewport", {{"width", 1}, {"height", 1}, {"distance", 1}}},
      {"camera", {{"position", {0, 0, -5}}}},
      {"models", models},
      {"instances", instances},
  };
  if (!lighting.is_null()) scene["lighting"] = lighting;
  return scene.dump(2);
}

const nlohmann::json kHeadlight = {
    {"ambient", 0.1}, {"lights", {{{"type", "directional"}, {"direction", {0, 0, -1}}, {"intensity", 0.9}}}}};

nlohmann::json OneInstance(const char* model = "mesh") { return nlohmann::json::array({{{"model", model}}}); }

// A scene file in `dir` and the OBJ files it names, written there first.
std::filesystem::path WriteScene(const test::TempDir& dir, const std::string& scene_text,
                                 const std::vector<std::pair<std::string, std::string>>& objs) {
  for (const auto& [name, text] : objs) {
    std::filesystem::create_directories((dir / name).parent_path());
    test::WriteFile(dir / name, text);
  }
  test::WriteFile(dir / "scene.json", scene_text);
  return dir / "scene.json";
}

SceneError LoadError(const std::filesystem::path& file) {
  try {
    (void)LoadScene(file);
  } catch (const SceneError& e) {
    return e;
  }
  throw std::runtime_error("no error loading " + file.string());
}

SceneError ParseError(const std::string& text) {
  try {
    (void)ParseScene(text, "lit.json");
  } catch (const SceneError& e) {
    return e;
  }
  throw std::runtime_error("no error for:\n" + text);
}

// Restores the current directory when it dies.
class CurrentDirectory {
 public:
  explicit CurrentDirectory(const std::filesystem::path& to) : before_(std::filesystem::current_path()) {
    std::filesystem::current_path(to);
  }
  ~CurrentDirectory() { std::filesystem::current_path(before_); }
  CurrentDirectory(const CurrentDirectory&) = delete;
  CurrentDirectory& operator=(const CurrentDirectory&) = delete;

 private:
  std::filesystem::path before_;
};

}  // namespace

TEST_CASE("An OBJ model: its path relative to the scene file, the default colour, unlit without lighting",
          "[scene][obj]") {
  const test::TempDir dir;
  const auto file = WriteScene(dir, SceneText({{"mesh", {{"obj", "meshes/tri.obj"}}}}, OneInstance()),
                               {{"meshes/tri.obj", kTriangleObj}});
  // The tests run elsewhere: the path must be found from the scene's directory, not this one.
  REQUIRE(std::filesystem::current_path() != dir.path());
  const Scene scene = LoadScene(file);
  REQUIRE(scene.models.size() == 1);
  const Model& model = scene.models[0];
  REQUIRE(model.name == "mesh");
  REQUIRE(model.source == "meshes/tri.obj");
  REQUIRE(model.vertices == std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
  REQUIRE(model.triangles.size() == 1);
  REQUIRE(model.triangles[0].v == std::array<std::uint32_t, 3>{0, 1, 2});
  REQUIRE(model.triangles[0].colour == kDefaultObjColour);
  REQUIRE(model.shading == Shading::kUnlit);
  REQUIRE(!scene.lighting);
}

TEST_CASE("An OBJ model's colour, and materials colouring usemtl groups", "[scene][obj]") {
  const test::TempDir dir;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nusemtl skin\nf 1 2 3\nusemtl eyes\nf 1 2 3\n";
  const nlohmann::json models = {
      {"mesh", {{"obj", "m.obj"}, {"colour", "blue"}, {"materials", {{"skin", {200, 150, 120}}}}}}};
  const Scene scene = LoadScene(WriteScene(dir, SceneText(models, OneInstance()), {{"m.obj", obj}}));
  const auto& t = scene.models[0].triangles;
  REQUIRE(t.size() == 3);
  REQUIRE(t[0].colour == Rgb8{0, 0, 255});      // no material: the model's colour
  REQUIRE(t[1].colour == Rgb8{200, 150, 120});  // skin
  REQUIRE(t[2].colour == Rgb8{0, 0, 255});      // eyes: no entry, the model's colour
}

TEST_CASE("A material the OBJ file never uses is an error naming it", "[scene][obj][bad-input]") {
  const test::TempDir dir;
  const std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl green\nf 1 2 3\nusemtl other\nf 1 2 3\n";
  const nlohmann::json misspelt = {{"mesh", {{"obj", "m.obj"}, {"materials", {{"green", "green"}, {"gren", "red"}}}}}};
  const SceneError e = LoadError(WriteScene(dir, SceneText(misspelt, OneInstance()), {{"m.obj", obj}}));
  REQUIRE(e.file() == (dir / "scene.json").string());
  REQUIRE(e.where() == "models.mesh.materials.gren");
  REQUIRE(e.problem() == "the OBJ file never uses material \"gren\" (did you mean \"green\"?); it uses green, other");

  const nlohmann::json none = {{"mesh", {{"obj", "m.obj"}, {"materials", {{"skin", "red"}}}}}};
  const SceneError no_usemtl = LoadError(WriteScene(dir, SceneText(none, OneInstance()), {{"m.obj", kTriangleObj}}));
  REQUIRE(no_usemtl.where() == "models.mesh.materials.skin");
  REQUIRE(no_usemtl.problem() == "the OBJ file never uses material \"skin\": it has no usemtl lines");
}

TEST_CASE("Shading defaults: with lighting gouraud if the OBJ has normals, else flat, and without it unlit",
          "[scene][obj][lighting]") {
  const test::TempDir dir;
  const nlohmann::json models = {
      {"smooth", {{"obj", "quad.obj"}}},
      {"faceted", {{"obj", "tri.obj"}}},
      {"kept", {{"obj", "quad.obj"}, {"shading", "unlit"}}},
      {"forced", {{"obj", "tri.obj"}, {"shading", "gouraud"}}},
      {"written", {{"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {"triangles", {{0, 1, 2, "red"}}}}},
      {"written_unlit",
       {{"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {"triangles", {{0, 1, 2, "red"}}}, {"shading", "unlit"}}},
  };
  const nlohmann::json instances = nlohmann::json::array({{{"model", "smooth"}}});
  const std::vector<std::pair<std::string, std::string>> objs = {{"quad.obj", kQuadWithNormalsObj},
                                                                 {"tri.obj", kTriangleObj}};
  const auto shading_of = [](const Scene& scene, const std::string& name) {
    for (const Model& m : scene.models) {
      if (m.name == name) return m.shading;
    }
    throw std::runtime_error("no model " + name);
  };

  const Scene lit = LoadScene(WriteScene(dir, SceneText(models, instances, kHeadlight), objs));
  REQUIRE(shading_of(lit, "smooth") == Shading::kGouraud);
  REQUIRE(shading_of(lit, "faceted") == Shading::kFlat);
  REQUIRE(shading_of(lit, "kept") == Shading::kUnlit);
  REQUIRE(shading_of(lit, "forced") == Shading::kGouraud);
  REQUIRE(shading_of(lit, "written") == Shading::kFlat);
  REQUIRE(shading_of(lit, "written_unlit") == Shading::kUnlit);
  // The OBJ's normals and which corner names which, as the file wrote them.
  const Model& smooth = lit.models[static_cast<std::size_t>(
      std::find_if(lit.models.begin(), lit.models.end(), [](const Model& m) { return m.name == "smooth"; }) -
      lit.models.begin())];
  REQUIRE(smooth.normals == std::vector<glm::dvec3>{{0, 0, 1}});
  REQUIRE(smooth.triangle_normals == std::vector<std::array<std::uint32_t, 3>>{{0, 0, 0}, {0, 0, 0}});

  nlohmann::json unlit_models = models;
  unlit_models.erase("forced");
  const Scene unlit = LoadScene(WriteScene(dir, SceneText(unlit_models, instances), objs));
  for (const Model& m : unlit.models) {
    INFO(m.name);
    REQUIRE(m.shading == Shading::kUnlit);
  }
}

TEST_CASE("A shading other than unlit without the scene's lighting is an error", "[scene][obj][lighting][bad-input]") {
  const nlohmann::json flat = {
      {"mesh", {{"vertices", {{0, 0, 0}}}, {"triangles", {{0, 0, 0, "red"}}}, {"shading", "flat"}}}};
  const SceneError e = ParseError(SceneText(flat, OneInstance()));
  REQUIRE(e.where() == "models.mesh.shading");
  REQUIRE(e.problem() == "\"flat\" shading needs the scene's \"lighting\"; without it every model is unlit");
  const nlohmann::json unknown = {
      {"mesh", {{"vertices", {{0, 0, 0}}}, {"triangles", {{0, 0, 0, "red"}}}, {"shading", "gouraurd"}}}};
  const SceneError u = ParseError(SceneText(unknown, OneInstance(), kHeadlight));
  REQUIRE(u.where() == "models.mesh.shading");
  REQUIRE(u.problem() == "expected \"unlit\", \"flat\" or \"gouraud\", found \"gouraurd\" (did you mean \"gouraud\"?)");
}

TEST_CASE("Lighting: an ambient term, directional and point lights", "[scene][lighting]") {
  const nlohmann::json models = {
      {"mesh", {{"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {"triangles", {{0, 1, 2, "red"}}}}}};
  const nlohmann::json lighting = {{"ambient", 0.2},
                                   {"lights",
                                    {{{"type", "directional"}, {"direction", {1, 4, -3}}, {"intensity", 0.6}},
                                     {{"type", "point"}, {"position", {2, 1, 0}}, {"intensity", 0}}}}};
  const Scene scene = ParseScene(SceneText(models, OneInstance(), lighting), "lit.json");
  REQUIRE(scene.lighting);
  REQUIRE(scene.lighting->ambient == 0.2);
  REQUIRE(scene.lighting->lights.size() == 2);
  REQUIRE(scene.lighting->lights[0].kind == Light::Kind::kDirectional);
  REQUIRE(scene.lighting->lights[0].vector == glm::dvec3(1, 4, -3));
  REQUIRE(scene.lighting->lights[0].intensity == 0.6);
  REQUIRE(scene.lighting->lights[1].kind == Light::Kind::kPoint);
  REQUIRE(scene.lighting->lights[1].vector == glm::dvec3(2, 1, 0));
  REQUIRE(scene.lighting->lights[1].intensity == 0);
  // Ambient defaults to 0; no lights at all is allowed (ambient only).
  const Scene ambient = ParseScene(SceneText(models, OneInstance(), {{"lights", nlohmann::json::array()}}), "lit.json");
  REQUIRE(ambient.lighting);
  REQUIRE(ambient.lighting->ambient == 0);
  REQUIRE(ambient.lighting->lights.empty());
}

TEST_CASE("Bad lighting: each problem named at its JSON path", "[scene][lighting][bad-input]") {
  const nlohmann::json models = {
      {"mesh", {{"vertices", {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}}, {"triangles", {{0, 1, 2, "red"}}}}}};
  const auto light = [](nlohmann::json l) { return nlohmann::json{{"ambient", 0.1}, {"lights", {std::move(l)}}}; };
  struct Case {
    const char* what;
    nlohmann::json lighting;
    std::string where, problem;
  };
  const std::vector<Case> cases = {
      {"negative ambient",
       {{"ambient", -0.1}, {"lights", nlohmann::json::array()}},
       "lighting.ambient",
       "must be 0 or more, found -0.1"},
      {"missing lights", {{"ambient", 0.1}}, "lighting", "missing required key \"lights\""},
      {"misspelt key",
       {{"ambiant", 0.1}, {"lights", nlohmann::json::array()}},
       "lighting",
       "unknown key \"ambiant\" (did you mean \"ambient\"?)"},
      {"lights not a list", {{"lights", 1}}, "lighting.lights", "expected an array, found a number"},
      {"negative intensity", light({{"type", "point"}, {"position", {0, 0, 0}}, {"intensity", -1}}),
       "lighting.lights[0].intensity", "must be 0 or more, found -1"},
      {"missing intensity", light({{"type", "point"}, {"position", {0, 0, 0}}}), "lighting.lights[0]",
       "missing required key \"intensity\""},
      {"zero direction", light({{"type", "directional"}, {"direction", {0, 0, 0}}, {"intensity", 1}}),
       "lighting.lights[0].direction", "a directional light's direction must not be the zero vector"},
      {"direction too short", light({{"type", "directional"}, {"direction", {1e-12, 0, 0}}, {"intensity", 1}}),
       "lighting.lights[0].direction", "absurdly short"},
      {"unknown type", light({{"type", "spot"}, {"intensity", 1}}), "lighting.lights[0].type",
       "expected \"directional\" or \"point\", found \"spot\""},
      {"misspelt type", light({{"type", "directonal"}, {"intensity", 1}}), "lighting.lights[0].type",
       "(did you mean \"directional\"?)"},
      {"missing type", light({{"intensity", 1}}), "lighting.lights[0]", "missing required key \"type\""},
      {"a point light's key on a directional light",
       light({{"type", "directional"}, {"position", {0, 0, 0}}, {"intensity", 1}}), "lighting.lights[0]",
       "unknown key \"position\"; valid keys here: type, direction, intensity"},
      {"direction not a vector", light({{"type", "directional"}, {"direction", "down"}, {"intensity", 1}}),
       "lighting.lights[0].direction", "expected [x, y, z], found a string"},
      {"lighting not an object", true, "lighting", "expected an object, found a boolean"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const SceneError e = ParseError(SceneText(models, OneInstance(), c.lighting));
    INFO(e.what());
    REQUIRE(e.file() == "lit.json");
    REQUIRE(e.where() == c.where);
    REQUIRE(e.problem().find(c.problem) != std::string::npos);
  }
  // A number beyond double, located by the JSON parser's own error path.
  const std::string text =
      SceneText(models, OneInstance(), light({{"type", "point"}, {"position", {0, 0, 0}}, {"intensity", 12345}}));
  const std::string huge = std::string(text).replace(text.find("12345"), 5, "1e999");
  const SceneError e = ParseError(huge);
  REQUIRE(e.where() == "lighting.lights[0].intensity");
  REQUIRE(e.problem().find("out of range for a double") != std::string::npos);
}

TEST_CASE("A model is either obj or vertices, and colour and materials belong to obj", "[scene][obj][bad-input]") {
  const nlohmann::json both = {{"mesh", {{"obj", "m.obj"}, {"vertices", {{0, 0, 0}}}}}};
  const SceneError e = ParseError(SceneText(both, OneInstance()));
  REQUIRE(e.where() == "models.mesh.vertices");
  REQUIRE(e.problem() == "a model is read from \"obj\" or written as \"vertices\" and \"triangles\", not both");
  const nlohmann::json coloured = {
      {"mesh", {{"vertices", {{0, 0, 0}}}, {"triangles", {{0, 0, 0, "red"}}}, {"colour", "red"}}}};
  const SceneError c = ParseError(SceneText(coloured, OneInstance()));
  REQUIRE(c.where() == "models.mesh.colour");
  REQUIRE(c.problem().find("only for a model read from an OBJ file (\"obj\")") != std::string::npos);
  const nlohmann::json typo = {{"mesh", {{"ojb", "m.obj"}}}};
  const SceneError t = ParseError(SceneText(typo, OneInstance()));
  REQUIRE(t.where() == "models.mesh");
  REQUIRE(t.problem().find("unknown key \"ojb\" (did you mean \"obj\"?)") != std::string::npos);
  const SceneError empty = ParseError(SceneText({{"mesh", {{"obj", ""}}}}, OneInstance()));
  REQUIRE(empty.where() == "models.mesh.obj");
  REQUIRE(empty.problem() == "expected the path of an OBJ file, found \"\"");
}

TEST_CASE("A missing OBJ file: the path as the scene wrote it, where it was looked for, and the scene",
          "[scene][obj][bad-input]") {
  const test::TempDir dir;
  const auto file = WriteScene(dir, SceneText({{"mesh", {{"obj", "meshes/none.obj"}}}}, OneInstance()), {});
  const SceneError e = LoadError(file);
  REQUIRE(e.file() == file.string());
  REQUIRE(e.where() == "models.mesh.obj");
  REQUIRE(e.problem() ==
          "OBJ file \"meshes/none.obj\" (looked for " + (dir / "meshes/none.obj").string() + "): no such file");
  // Through the command line: one line, exit code 2.
  const test::CliResult r = test::RunCli({"explain", file.string()});
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.err == "twinraster: " + file.string() + ": models.mesh.obj: OBJ file \"meshes/none.obj\" (looked for " +
                       (dir / "meshes/none.obj").string() + "): no such file\n");

  std::filesystem::create_directories(dir / "meshes" / "dir.obj");
  const auto directory = WriteScene(dir, SceneText({{"mesh", {{"obj", "meshes/dir.obj"}}}}, OneInstance()), {});
  REQUIRE(LoadError(directory).problem().find("): is a directory, not an OBJ file") != std::string::npos);
}

TEST_CASE("A bad OBJ file a scene names: one line naming the OBJ file and its line, exit code 2",
          "[scene][obj][bad-input]") {
  const test::TempDir dir;
  const auto file = WriteScene(dir, SceneText({{"mesh", {{"obj", "meshes/bad.obj"}}}}, OneInstance()),
                               {{"meshes/bad.obj", "v 0 0 0\nv 1 0 0\nv 0 1 zero\nf 1 2 3\n"}});
  const test::CliResult r = test::RunCli({"explain", file.string()});
  REQUIRE(r.exit_code == 2);
  REQUIRE(r.out.empty());
  REQUIRE(r.err == "twinraster: " + (dir / "meshes/bad.obj").string() + ": line 3: v: \"zero\" is not a number\n");
}

TEST_CASE("Without a scene file, OBJ paths start from the current directory", "[scene][obj]") {
  const test::TempDir dir;
  test::WriteFile(dir / "tri.obj", kTriangleObj);
  const std::string text = SceneText({{"mesh", {{"obj", "tri.obj"}}}}, OneInstance());
  {
    const CurrentDirectory here(dir.path());
    REQUIRE(ParseScene(text, "<stdin>").models[0].triangles.size() == 1);
  }
  REQUIRE(ParseScene(text, "<stdin>", dir.path()).models[0].source == "tri.obj");  // or from a directory given
  const SceneError e = ParseError(text);  // here, in the tests' directory, there is no tri.obj
  REQUIRE(e.problem() == "OBJ file \"tri.obj\": no such file");
}

TEST_CASE("A zero scale is an error only for an instance of a lit model", "[scene][lighting][bad-input]") {
  const nlohmann::json vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const nlohmann::json triangles = {{0, 1, 2, "red"}};
  const nlohmann::json models = {{"lit", {{"vertices", vertices}, {"triangles", triangles}}},
                                 {"plain", {{"vertices", vertices}, {"triangles", triangles}, {"shading", "unlit"}}}};
  const auto instance = [](const char* model, nlohmann::json transform) {
    return nlohmann::json::array({{{"model", "plain"}}, {{"model", model}, {"transform", std::move(transform)}}});
  };
  struct Case {
    const char* what;
    nlohmann::json transform;
    std::string where;
  };
  const std::vector<Case> cases = {
      {"a zero scale", {{"scale", 0}}, "instances[1].transform.scale"},
      {"one zero factor", {{"scale", {1, -0.0, 2}}, {"translation", {0, 0, 5}}}, "instances[1].transform.scale[1]"},
      {"a zero scale step",
       {{{"translation", {0, 0, 5}}}, {{"scale", {2, 2, 0}}}},
       "instances[1].transform[1].scale[2]"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const SceneError e = ParseError(SceneText(models, instance("lit", c.transform), kHeadlight));
    REQUIRE(e.where() == c.where);
    REQUIRE(e.problem() ==
            "a lit model (\"lit\", flat shading) cannot be scaled by 0: the normal matrix, the inverse transpose of "
            "M_Model, does not exist for a zero scale (use a non-zero scale, or \"shading\": \"unlit\")");
    // An unlit model, or any model in a scene without lighting, may be flattened.
    REQUIRE(ParseScene(SceneText(models, instance("plain", c.transform), kHeadlight), "lit.json").instances.size() ==
            2);
    REQUIRE(ParseScene(SceneText(models, instance("lit", c.transform)), "unlit.json").instances.size() == 2);
  }
  // A grid's copies share the instance's transform: one error, at the instance.
  nlohmann::json grid = instance("lit", {{"scale", {0, 1, 1}}});
  grid[1]["grid"] = {{"count", {2, 2, 2}}, {"spacing", {1, 1, 1}}};
  REQUIRE(ParseError(SceneText(models, grid, kHeadlight)).where() == "instances[1].transform.scale[0]");
}

TEST_CASE("A lit model's scales must keep its normal matrix within float's range", "[scene][lighting][bad-input]") {
  // Invertible in exact arithmetic, but 1e-110 cubed underflows double's determinant, and past
  // 1e-30 the inverse transpose outgrows float: before, the first ended as an internal error
  // (exit 4) and the second was drawn with infinities in its normal matrix.
  const nlohmann::json vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  const nlohmann::json models = {{"lit", {{"vertices", vertices}, {"triangles", {{0, 1, 2, "red"}}}}}};
  const auto instance = [](nlohmann::json transform) {
    return nlohmann::json::array({{{"model", "lit"}, {"transform", std::move(transform)}}});
  };
  struct Case {
    const char* what;
    nlohmann::json transform;
    std::string where;
  };
  const std::vector<Case> cases = {
      {"a uniform scale of 1e-110", {{"scale", 1e-110}}, "instances[0].transform.scale"},
      {"one factor of 1e-40", {{"scale", {1, 1e-40, 1}}}, "instances[0].transform.scale"},
      {"five steps of 1e7 (a number is at most 1e12)",
       {{{"scale", 1e7}}, {{"scale", 1e7}}, {{"scale", 1e7}}, {{"scale", 1e7}}, {{"scale", 1e7}}},
       "instances[0].transform[4].scale"},
      {"two steps of 1e-20 each",
       {{{"scale", 1e-20}}, {{"translation", {0, 0, 5}}}, {{"scale", 1e-20}}},
       "instances[0].transform[2].scale"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const SceneError e = ParseError(SceneText(models, instance(c.transform), kHeadlight));
    CHECK(e.where() == c.where);
    CHECK_THAT(e.problem(), HasSubstring("a lit model (\"lit\", flat shading) is scaled beyond 1e-30..1e30"));
    CHECK(ParseScene(SceneText(models, instance(c.transform)), "unlit.json").instances.size() == 1);
  }
  // Within the range, however small: loaded.
  CHECK(ParseScene(SceneText(models, instance({{"scale", 1e-29}}), kHeadlight), "small.json").instances.size() == 1);
}

TEST_CASE("Scenes without lighting load as before: no lighting, every model unlit, no normals", "[scene][lighting]") {
  int unlit = 0;
  for (const auto& file : test::ShippedScenes()) {
    if (test::ReadFile(file).find("\"lighting\"") != std::string::npos) continue;
    INFO(file.string());
    const Scene scene = LoadScene(file);
    REQUIRE(!scene.lighting);
    for (const Model& m : scene.models) {
      REQUIRE(m.shading == Shading::kUnlit);
      REQUIRE(m.normals.empty());
      REQUIRE(m.triangle_normals.empty());
      REQUIRE(m.source.empty());
    }
    ++unlit;
  }
  CHECK(unlit == 46 - 9);  // of the 46 shipped scenes, 9 are lit
}

TEST_CASE("SceneForObj frames the mesh as tinyrenderer does: inside the canvas, front on, lit by a headlight",
          "[scene][obj]") {
  const test::TempDir dir;
  // A box from (2, -1, 5) to (4, 3, 6), off the origin and longer in y; a stray vertex far away
  // that no face names must not move the camera.
  std::string obj = "v 2 -1 5\nv 4 -1 5\nv 4 3 5\nv 2 3 5\nv 2 -1 6\nv 4 -1 6\nv 4 3 6\nv 2 3 6\nv 1000 1000 1000\n";
  obj += "f 1 2 3 4\nf 5 6 7 8\nf 1 2 6 5\nf 4 3 7 8\nf 1 4 8 5\nf 2 3 7 6\n";
  test::WriteFile(dir / "Box.OBJ", obj);
  const Scene scene = LoadSceneOrObj(dir / "Box.OBJ");  // the extension in any case
  REQUIRE(scene.name == "Box");
  REQUIRE(scene.canvas.width == 800);
  REQUIRE(scene.canvas.height == 800);
  REQUIRE(scene.models.size() == 1);
  REQUIRE(scene.models[0].shading == Shading::kFlat);  // no vn
  REQUIRE(scene.models[0].source == (dir / "Box.OBJ").string());
  REQUIRE(scene.instances.size() == 1);
  REQUIRE(scene.lighting);
  REQUIRE(scene.lighting->ambient == 0.1);
  REQUIRE(scene.lighting->lights.size() == 1);
  REQUIRE(scene.lighting->lights[0].kind == Light::Kind::kDirectional);
  REQUIRE(scene.lighting->lights[0].intensity == 0.9);

  // Model space to canvas pixels, by the chapter's chain done by hand.
  const Transform& transform = scene.instances[0].transform;
  const auto world = [&](glm::dvec3 p) { return transform.rotation * (p * transform.scale) + transform.translation; };
  const auto camera = [&](glm::dvec3 p) {
    return glm::transpose(scene.camera.rotation) * (world(p) - scene.camera.position);
  };
  const auto pixel = [&](glm::dvec3 p) {
    const glm::dvec3 c = camera(p);
    return glm::dvec2(
        scene.canvas.width / 2.0 + c.x * scene.viewport.distance / c.z * scene.canvas.width / scene.viewport.width,
        scene.canvas.height / 2.0 - c.y * scene.viewport.distance / c.z * scene.canvas.height / scene.viewport.height);
  };
  double left = 1e9, right = -1e9, top = 1e9, bottom = -1e9;
  for (const double x : {2.0, 4.0}) {
    for (const double y : {-1.0, 3.0}) {
      for (const double z : {5.0, 6.0}) {
        const glm::dvec3 corner(x, y, z);
        const double depth = camera(corner).z;
        REQUIRE(depth > scene.depth.near);
        REQUIRE(depth < scene.depth.far);
        const glm::dvec2 p = pixel(corner);
        left = std::min(left, p.x), right = std::max(right, p.x), top = std::min(top, p.y),
        bottom = std::max(bottom, p.y);
      }
    }
  }
  // Inside the canvas with a margin, and large in it (framed, not a speck in the distance).
  REQUIRE(left > 40);
  REQUIRE(top > 40);
  REQUIRE(right < 760);
  REQUIRE(bottom < 760);
  REQUIRE(bottom - top > 400);
  // Centred on the box's centre.
  const glm::dvec2 centre = pixel({3, 1, 5.5});
  REQUIRE(std::abs(centre.x - 400) < 1e-9);
  REQUIRE(std::abs(centre.y - 400) < 1e-9);
  // tinyrenderer's view of a right-handed OBJ: +X to the right, +Y up, and the +Z face (the
  // model's front) nearer the camera than the -Z face.
  REQUIRE(pixel({4, 1, 5.5}).x > pixel({2, 1, 5.5}).x);
  REQUIRE(pixel({3, 3, 5.5}).y < pixel({3, -1, 5.5}).y);
  REQUIRE(camera({3, 1, 6}).z < camera({3, 1, 5}).z);
  // The camera is up, right and in front of the model, as tinyrenderer's eye (1, 1, 3).
  const glm::dvec3 eye_in_model = scene.camera.position / transform.scale;
  const glm::dvec3 from_centre = glm::normalize(eye_in_model - glm::dvec3(3, 1, 5.5));
  REQUIRE(glm::length(from_centre - glm::normalize(glm::dvec3(1, 1, 3))) < 1e-12);
  // The headlight shines from the camera: l, toward the light, points at the eye.
  REQUIRE(glm::length(glm::normalize(scene.lighting->lights[0].vector) -
                      glm::normalize(scene.camera.position - world({3, 1, 5.5}))) < 1e-12);
}

TEST_CASE("SceneForObj: Gouraud shading when the OBJ has normals, and LoadSceneOrObj loads other files as scenes",
          "[scene][obj]") {
  const test::TempDir dir;
  test::WriteFile(dir / "quad.obj", kQuadWithNormalsObj);
  const Scene scene = SceneForObj(dir / "quad.obj");
  REQUIRE(scene.models[0].shading == Shading::kGouraud);
  REQUIRE(scene.models[0].triangle_normals.size() == 2);
  const Scene json = LoadSceneOrObj(test::SourcePath("scenes/cgfs-scene.json"));
  REQUIRE(json.name == "cgfs-scene");
  REQUIRE(!json.lighting);
  try {
    (void)LoadSceneOrObj(dir / "none.obj");
    FAIL("no error");
  } catch (const SceneError& e) {
    REQUIRE(e.file() == (dir / "none.obj").string());
    REQUIRE(e.problem() == "no such file");
  }
}
