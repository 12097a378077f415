// Transforms written as lists (figures 10-4 and 10-5): steps apply in the order written, a grid
// moves the whole result in world space, and explain shows each step.
#include "chain/matrices.hpp"
#include "chain/vertex_trace.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <numbers>
#include <string>

using namespace twinraster;

namespace {

Scene Load(const std::string& name) { return LoadScene(test::SourcePath("scenes/" + name + ".json")); }

std::string ListScene(const std::string& transform, const std::string& grid = "") {
  return R"({"canvas": {"width": 64, "height": 48}, "viewport": {"width": 1, "height": 1, "distance": 1},
             "camera": {"position": [0, 0, 0]},
             "models": {"tri": {"vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]], "triangles": [[0, 1, 2, "red"]]}},
             "instances": [{"model": "tri", "transform": )" +
         transform + grid + "}]}";
}

glm::dvec3 World(const Transform& t, glm::dvec3 v) { return glm::dvec3(ModelMatrix(t) * glm::dvec4(v, 1.0)); }

}  // namespace

TEST_CASE("Figures 10-4 and 10-5: rotate then translate is not translate then rotate", "[chain][transform-list]") {
  const double s = std::sin(std::numbers::pi / 4), c = std::cos(std::numbers::pi / 4);
  const Transform rotate_translate = Load("cgfs-figure-10-4").instances[1].transform;
  const Transform translate_rotate = Load("cgfs-figure-10-5").instances[1].transform;
  REQUIRE(rotate_translate.steps);
  REQUIRE(rotate_translate.steps->size() == 2);
  // 10-4: the cube turns about its own centre, which then moves to (0, 0, 5).
  const glm::dvec3 centre_4 = World(rotate_translate, {0, 0, 0});
  CHECK(centre_4 == glm::dvec3(0, 0, 5));
  // 10-5: the centre moves to (0, 0, 5) first, then the chapter's Y rotation by 45 degrees (rows
  // [cos, 0, -sin] [0, 1, 0] [sin, 0, cos]) swings it around the origin to (-5 sin 45, 0, 5 cos 45).
  const glm::dvec3 centre_5 = World(translate_rotate, {0, 0, 0});
  CHECK(centre_5.x == Approx(-5 * s).margin(1e-12));
  CHECK(centre_5.y == Approx(0).margin(1e-12));
  CHECK(centre_5.z == Approx(5 * c).margin(1e-12));
  // Both keep the cube's shape: a corner is sqrt(3) from the centre either way.
  CHECK(glm::length(World(rotate_translate, {1, 1, 1}) - centre_4) == Approx(std::sqrt(3.0)));
  CHECK(glm::length(World(translate_rotate, {1, 1, 1}) - centre_5) == Approx(std::sqrt(3.0)));
  // The matrix product and Listing 10-4's step-by-step application agree.
  for (const Transform* t : {&rotate_translate, &translate_rotate}) {
    const glm::dvec3 stepped = ApplyTransform({1, -1, 1}, *t), composed = World(*t, {1, -1, 1});
    CHECK(glm::length(stepped - composed) < 1e-12);
  }
}

TEST_CASE("A transform list: steps in the order written, the object form unchanged", "[chain][transform-list]") {
  const Scene listed =
      ParseScene(ListScene(R"([{"scale": 2}, {"translation": [1, 0, 0]}, {"scale": [1, 3, 1]}])"), "list.json");
  // (x, y, z) -> (2x, 2y, 2z) -> (2x + 1, 2y, 2z) -> (2x + 1, 6y, 2z)
  CHECK(World(listed.instances[0].transform, {1, 1, 1}) == glm::dvec3(3, 6, 2));
  const Scene empty = ParseScene(ListScene("[]"), "empty.json");
  CHECK(ModelMatrix(empty.instances[0].transform) == glm::dmat4(1.0));
  // The object form is scale, rotate, translate, with no list.
  const Scene object = ParseScene(ListScene(R"({"scale": 2, "translation": [1, 0, 0]})"), "object.json");
  CHECK_FALSE(object.instances[0].transform.steps);
  CHECK(World(object.instances[0].transform, {1, 1, 1}) == glm::dvec3(3, 2, 2));
}

TEST_CASE("A grid of a transform list moves each copy after the steps, in world space",
          "[chain][transform-list][grid]") {
  const Scene scene =
      ParseScene(ListScene(R"([{"translation": [0, 0, 5]}, {"rotation": {"axis": "y", "degrees": 90}}])",
                           R"(, "grid": {"count": [2, 1, 1], "spacing": [10, 1, 1]})"),
                 "grid.json");
  REQUIRE(scene.instances.size() == 2);
  REQUIRE(scene.instances[0].transform.steps == scene.instances[1].transform.steps);  // shared, not copied
  // The list takes the origin to (-5, 0, 0) (a quarter turn of (0, 0, 5)); the copies sit 10 apart
  // around that, at x = -5 - 5 and -5 + 5.
  const glm::dvec3 a = World(scene.instances[0].transform, {0, 0, 0}),
                   b = World(scene.instances[1].transform, {0, 0, 0});
  CHECK(a.x == Approx(-10));
  CHECK(b.x == Approx(0).margin(1e-12));
  CHECK(a.z == Approx(0).margin(1e-12));
}

TEST_CASE("explain shows each step of a transform list and their product", "[chain][transform-list][explain]") {
  const std::string file = test::SourcePath("scenes/cgfs-figure-10-5.json").string();
  const test::CliResult text = test::RunCli({"explain", file, "--instance", "1", "--vertex", "0"});
  INFO(text.err);
  REQUIRE(text.exit_code == 0);
  for (const char* expected :
       {"a list of 2 steps, applied in the order written", "step 1: I_T1", "step 2: I_R2", "M_Model = I_R2 · I_T1"}) {
    INFO(expected);
    CHECK(text.out.find(expected) != std::string::npos);
  }
  const test::CliResult json = test::RunCli({"explain", file, "--instance", "1", "--json"});
  REQUIRE(json.exit_code == 0);
  const auto j = nlohmann::json::parse(json.out);
  const auto& steps = j.at("instances").at(0).at("transform_steps");
  REQUIRE(steps.size() == 2);
  CHECK(steps[0].at("kind") == "translation");
  CHECK(steps[1].at("kind") == "rotation");
  CHECK(steps[0].at("matrix")[2][3] == 5.0);  // I_T's z offset, row-major
  CHECK(j.at("instances").at(0).at("model_matrix")[2][3] == Approx(5 * std::cos(std::numbers::pi / 4)));
}
