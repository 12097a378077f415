// "vertex_colours" in a scene file: one colour per vertex, read as names or [r, g, b], on JSON and
// OBJ models; a triangle's own colour becomes optional (its first vertex's by default), and every
// mistake is a SceneError naming the file, the JSON path and the problem.
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <string>

using namespace twinraster;

namespace {

// A square of four vertices and two triangles, with `model`'s keys merged over it.
nlohmann::json Square(const nlohmann::json& model) {
  nlohmann::json square = {{"vertices", {{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}}},
                           {"triangles", {{0, 1, 2, "red"}, {0, 2, 3, "red"}}}};
  square.update(model);
  return {{"canvas", {{"width", 32}, {"height", 32}}},
          {"viewport", {{"width", 1}, {"height", 1}, {"distance", 1}}},
          {"camera", {{"position", {0, 0, 0}}}},
          {"models", {{"square", square}}},
          {"instances", {{{"model", "square"}, {"transform", {{"translation", {0, 0, 4}}}}}}}};
}

Scene Parse(const nlohmann::json& scene) { return ParseScene(scene.dump(), "vc.json", test::SourcePath("scenes")); }

// The SceneError `scene` throws: where and what.
SceneError ErrorOf(const nlohmann::json& scene) {
  try {
    Parse(scene);
  } catch (const SceneError& e) {
    return e;
  }
  FAIL("the scene was read without an error: " << scene.dump());
  return SceneError("", "", "");
}

}  // namespace

TEST_CASE("vertex_colours: one colour per vertex, names or [r, g, b], and triangle colours then optional",
          "[scene][vertex-colours]") {
  const Scene scene = Parse(Square({{"vertex_colours", {"red", {10, 20, 30}, "white", {0, 0, 255}}},
                                    {"triangles", {{0, 1, 2}, {2, 3, 0, "green"}}}}));
  const Model& m = scene.models.at(0);
  REQUIRE(m.vertex_colours.size() == 4);
  CHECK(m.vertex_colours[0] == Rgb8{255, 0, 0});
  CHECK(m.vertex_colours[1] == Rgb8{10, 20, 30});
  CHECK(m.vertex_colours[2] == Rgb8{255, 255, 255});
  CHECK(m.vertex_colours[3] == Rgb8{0, 0, 255});
  // Left out: the first vertex's colour (for a wireframe and the book's rules); written: kept.
  CHECK(m.triangles[0].colour == Rgb8{255, 0, 0});
  CHECK(m.triangles[1].colour == Rgb8{0, 255, 0});
  CHECK(m.shading == Shading::kUnlit);

  // Without the key: no vertex colours, as before.
  CHECK(Parse(Square(nlohmann::json::object())).models.at(0).vertex_colours.empty());
}

TEST_CASE("vertex_colours on an OBJ model count the OBJ file's vertices", "[scene][vertex-colours][obj]") {
  // gem.obj has 33 vertices (v lines).
  nlohmann::json scene = Square(nlohmann::json::object());
  nlohmann::json colours = nlohmann::json::array();
  for (int i = 0; i < 33; ++i) colours.push_back({i * 7, 255 - i * 7, 100});
  scene["models"]["square"] = {{"obj", "meshes/gem.obj"}, {"vertex_colours", colours}};
  const Scene parsed = Parse(scene);
  const Model& gem = parsed.models.at(0);
  REQUIRE(gem.vertices.size() == 33);
  REQUIRE(gem.vertex_colours.size() == 33);
  CHECK(gem.vertex_colours[32] == Rgb8{224, 31, 100});

  colours.erase(colours.begin());
  scene["models"]["square"]["vertex_colours"] = colours;
  const SceneError e = ErrorOf(scene);
  CHECK(e.where() == "models.square.vertex_colours");
  CHECK(e.problem() == "32 colours for 33 vertices: give one colour per vertex");
}

TEST_CASE("Bad vertex_colours: each mistake names its JSON path and the problem",
          "[scene][vertex-colours][bad-input]") {
  struct Bad {
    const char* what;
    nlohmann::json model;
    std::string where, problem;
  };
  const nlohmann::json four = {"red", "green", "blue", "white"};
  const std::vector<Bad> cases = {
      {"too few",
       {{"vertex_colours", {"red", "green", "blue"}}},
       "models.square.vertex_colours",
       "3 colours for 4 vertices: give one colour per vertex"},
      {"too many",
       {{"vertex_colours", {"red", "green", "blue", "red", "red"}}},
       "models.square.vertex_colours",
       "5 colours for 4 vertices"},
      {"not a list",
       {{"vertex_colours", "red"}},
       "models.square.vertex_colours",
       "expected a list of colours, one per vertex, found a string"},
      {"unknown name",
       {{"vertex_colours", {"red", "gren", "blue", "red"}}},
       "models.square.vertex_colours[1]",
       "unknown colour \"gren\" (did you mean \"green\"?)"},
      {"channel out of range",
       {{"vertex_colours", {"red", "red", {0, 0, 256}, "red"}}},
       "models.square.vertex_colours[2][2]",
       "expected an integer in 0..255, found 256"},
      {"two channels",
       {{"vertex_colours", {"red", {1, 2}, "red", "red"}}},
       "models.square.vertex_colours[1]",
       "expected an array of 3 elements, found 2"},
      {"a triangle without a colour and no vertex colours",
       {{"triangles", {{0, 1, 2}, {0, 2, 3, "red"}}}},
       "models.square.triangles[0]",
       "a triangle without a colour needs the model's \"vertex_colours\""},
      {"a triangle of five",
       {{"vertex_colours", four}, {"triangles", {{0, 1, 2, "red", 3}}}},
       "models.square.triangles[0]",
       "expected an array of 3 or 4 elements, found 5"},
      {"a triangle of two",
       {{"vertex_colours", four}, {"triangles", {{0, 1}}}},
       "models.square.triangles[0]",
       "expected an array of 3 or 4 elements, found 2"},
      {"an index out of range",
       {{"vertex_colours", four}, {"triangles", {{0, 1, 4}}}},
       "models.square.triangles[0][2]",
       "expected an integer in 0..3, found 4"},
      {"a misspelt key", {{"vertex_colors", four}}, "models.square", "did you mean \"vertex_colours\"?"},
  };
  for (const Bad& c : cases) {
    INFO(c.what);
    const SceneError e = ErrorOf(Square(c.model));
    CHECK(e.file() == "vc.json");
    CHECK(e.where() == c.where);
    CHECK_THAT(e.problem(), HasSubstring(c.problem));
  }
}
