// Every kind of bad scene file gets one clear message naming the file, the JSON path (or line and
// column) and the problem, and exit code 2: run through the real executable.
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

using namespace twinraster;

namespace {

struct BadCase {
  const char* what;
  std::string text;     // the whole scene file
  std::string where;    // expected JSON path or "line L, column C"
  std::string problem;  // expected words of the message
};

std::string Base() { return test::ReadFile(test::SourcePath("scenes/cgfs-transforms.json")); }

// The shipped transforms scene with one value replaced (a JSON pointer) or removed (null).
std::string With(const std::string& pointer, const nlohmann::json& value) {
  nlohmann::ordered_json scene = nlohmann::ordered_json::parse(Base());
  if (value.is_null()) {
    const nlohmann::json::json_pointer p(pointer);
    scene[p.parent_pointer()].erase(p.back());
  } else {
    scene[nlohmann::ordered_json::json_pointer(pointer)] = value;
  }
  return scene.dump(2);
}

std::string Repeat(std::string text, const std::string& suffix, int times) {
  for (int i = 0; i < times; ++i) text += suffix;
  return text;
}

// `text` with its first `from` replaced by `to`.
std::string Replace(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  REQUIRE(at != std::string::npos);
  return text.replace(at, from.size(), to);
}

std::string LookAt(const nlohmann::json& eye, const nlohmann::json& center, const nlohmann::json& up) {
  return With("/camera", {{"eye", eye}, {"center", center}, {"up", up}});
}

std::vector<BadCase> Cases() {
  using nlohmann::json;
  return {
      {"syntax error", "{\n  \"canvas\": {\"width\": 600,, \"height\": 600}\n}", "line 2, column 27", "syntax error"},
      {"truncated file", "{\n  \"canvas\": {", "line 2, column 14", "unexpected end of input"},
      {"unknown key with a suggestion", With("/canvs", json::object()), "(top level)",
       "unknown key \"canvs\" (did you mean \"canvas\"?)"},
      {"unknown nested key", With("/instances/1/transform/scael", 2), "instances[1].transform",
       "did you mean \"scale\"?"},
      {"wrong type", With("/instances/1/transform/scale", "big"), "instances[1].transform.scale",
       "expected a number or [sx, sy, sz], found a string"},
      {"unknown projection", With("/viewport/projection", "orthografic"), "viewport.projection",
       "expected \"perspective\" or \"orthographic\", found \"orthografic\" (did you mean \"orthographic\"?)"},
      {"transform neither object nor list", With("/instances/1/transform", 5), "instances[1].transform",
       "expected an object (scale, rotation, translation) or a list of steps, found a number"},
      {"transform step with two keys",
       With("/instances/1/transform", json::array({{{"scale", 2}, {"translation", {0, 0, 5}}}})),
       "instances[1].transform[0]", "needs exactly one of \"scale\", \"rotation\" or \"translation\" (found 2 keys)"},
      {"transform step with no key", With("/instances/1/transform", json::array({json::object()})),
       "instances[1].transform[0]", "(found 0 keys)"},
      {"transform step with a misspelt key",
       With("/instances/1/transform", json::array({{{"rotaton", {{"axis", "y"}, {"degrees", 45}}}}})),
       "instances[1].transform[0]", "did you mean \"rotation\"?"},
      {"transform step not an object", With("/instances/1/transform", json::array({json::array({0, 0, 5})})),
       "instances[1].transform[0]", "expected an object"},
      {"wrong type in a vector", With("/camera/position/1", true), "camera.position[1]",
       "expected a number, found a boolean"},
      {"missing required key", With("/viewport/distance", nullptr), "viewport", "missing required key \"distance\""},
      {"missing model", With("/instances/0/model", "cub"), "instances[0].model",
       "no model named \"cub\" (did you mean \"cube\"?)"},
      {"triangle index out of range", With("/models/cube/triangles/3/2", 8), "models.cube.triangles[3][2]",
       "expected an integer in 0..7, found 8"},
      {"negative triangle index", With("/models/cube/triangles/0/0", -1), "models.cube.triangles[0][0]", "in 0..7"},
      {"unknown colour", With("/models/cube/triangles/0/3", "rde"), "models.cube.triangles[0][3]",
       "did you mean \"red\"?"},
      {"unknown colour: the names are listed", With("/models/cube/triangles/0/3", "Pink"),
       "models.cube.triangles[0][3]",
       "unknown colour \"Pink\"; use one of black, blue, cyan, gray, green, purple, red, white, yellow (in any "
       "case), or [r, g, b] with 0..255"},
      {"syntax error after a byte-order mark: placed as an editor shows it",
       "\xEF\xBB\xBF{\n  \"canvas\": {\"width\": 600,, \"height\": 600}\n}", "line 2, column 27", "syntax error"},
      {"a byte-order mark, then nothing", "\xEF\xBB\xBF", "line 1, column 1", "unexpected end of input"},
      {"number beyond double", "{\"canvas\": {\"width\": 1e999}}", "canvas.width",
       "number 1e999 is out of range for a double (line 1, column 22)"},
      {"number beyond double, nested", Replace(Base(), "\"distance\": 1", "\"distance\": 1e400"), "viewport.distance",
       "number 1e400 is out of range"},
      {"number beyond double in an array", "{\"instances\": [0, -1e999]}", "instances[1]",
       "number -1e999 is out of range"},
      {"duplicate key",
       "{\n  \"canvas\": {\"width\": 600,\n             \"height\": 600,\n             \"width\": 800}\n}",
       "canvas.width", "duplicate key \"width\", on line 2 and again on line 4"},
      {"duplicate top-level key", Replace(Base(), "\"viewport\": {", "\"viewport\": {}, \"viewport\": {"), "viewport",
       "duplicate key \"viewport\", on line 8 and again on line 8"},
      {"binary garbage (a PNG)", std::string("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16), "line 1, column 1",
       "not JSON text: binary data (byte 0x89)"},
      {"a NUL byte inside", std::string("{\n  \"canvas\"\0: 1}", 17), "line 2, column 11",
       "not JSON text: binary data (byte 0x00)"},
      {"nested too deep", "{\"comment\": " + std::string(100, '[') + std::string(100, ']') + "}",
       Repeat("comment", "[0]", 63), "nested deeper than 64 levels"},
      {"absurd number", With("/instances/0/transform/translation/2", 1e300), "instances[0].transform.translation[2]",
       "absurd"},
      {"canvas of zero width", With("/canvas/width", 0), "canvas.width", "expected an integer in 1..16384, found 0"},
      {"canvas too tall", With("/canvas/height", 16385), "canvas.height", "in 1..16384"},
      {"fractional canvas", With("/canvas/height", 10.5), "canvas.height", "expected an integer"},
      {"viewport width zero", With("/viewport/width", 0), "viewport.width", "must be greater than 0"},
      {"negative distance", With("/viewport/distance", -1), "viewport.distance", "must be greater than 0, found -1"},
      {"near zero", With("/depth", {{"near", 0}, {"far", 10}}), "depth.near", "must be greater than 0"},
      {"far not beyond near", With("/depth", {{"near", 5}, {"far", 5}}), "depth",
       "far (5) must be greater than near (5)"},
      {"up parallel to the view direction", LookAt({0, 0, 0}, {0, 0, 5}, {0, 0, 2}), "camera.up",
       "up is parallel to the view direction"},
      {"eye equals center", LookAt({1, 2, 3}, {1, 2, 3}, {0, 1, 0}), "camera.center", "center equals eye"},
      {"center a hair from eye", LookAt({1, 2, 3}, {1, 2, 3 + 1e-12}, {0, 1, 0}), "camera.center", "too close to eye"},
      {"both camera styles", With("/camera/eye", {0, 0, 0}), "camera", "use either position + rotation"},
      {"bad rotation axis", With("/camera/rotation/axis", "W"), "camera.rotation.axis",
       "unknown axis \"W\"; use \"x\", \"y\", \"z\" (in any case) or a vector [x, y, z]"},
      {"zero rotation axis", With("/camera/rotation/axis", {0, 0, 0}), "camera.rotation.axis", "zero vector"},
      {"top level not an object", "[1, 2, 3]", "(top level)", "expected an object, found an array"},
      {"empty file", "", "line 1, column 1", "unexpected end of input"},
      {"absurdly small viewport", With("/viewport/width", 1e-300), "viewport.width", "absurdly small"},
      {"absurdly small near", With("/depth", {{"near", 1e-300}, {"far", 10}}), "depth.near", "absurdly small"},
      {"reversed is not a boolean", With("/depth", {{"reversed", 1}}), "depth.reversed", "expected true or false"},
      {"grid count zero", With("/instances/0/grid", {{"count", {2, 0, 2}}, {"spacing", {1, 1, 1}}}),
       "instances[0].grid.count[1]", "expected an integer in 1..16777216, found 0"},
      {"grid count negative", With("/instances/0/grid", {{"count", {-3, 1, 1}}, {"spacing", {1, 1, 1}}}),
       "instances[0].grid.count[0]", "found -3"},
      {"grid too large", With("/instances/0/grid", {{"count", {1000, 1000, 17}}, {"spacing", {1, 1, 1}}}),
       "instances[0].grid.count", "more than 16777216 instances (this grid alone is 17000000)"},
      {"grid spacing not a number", With("/instances/0/grid", {{"count", {2, 2, 2}}, {"spacing", {1, "a", 1}}}),
       "instances[0].grid.spacing[1]", "expected a number, found a string"},
      {"grid spacing beyond double",
       Replace(With("/instances/0/grid", {{"count", {2, 2, 2}}, {"spacing", {1, 1, 3.125}}}), "3.125", "3.125e999"),
       "instances[0].grid.spacing[2]", "out of range"},
      {"grid with an unknown key",
       With("/instances/0/grid", {{"count", {2, 2, 2}}, {"spacing", {1, 1, 1}}, {"spcing", 1}}), "instances[0].grid",
       "did you mean \"spacing\"?"},
      {"grid not an object", With("/instances/0/grid", 5), "instances[0].grid", "expected an object, found a number"},
      {"steps out of range", With("/camera/rotation/steps", 0), "camera.rotation.steps", "in 1..10000000"},
  };
}

}  // namespace

TEST_CASE("Bad scene files: one message naming file, place and problem, exit code 2", "[bad-input]") {
  const test::TempDir dir;
  for (const BadCase& c : Cases()) {
    INFO(c.what);
    const auto file = dir / "bad.json";
    test::WriteFile(file, c.text);
    const test::CliResult r = test::RunCli({"explain", file.string()});
    INFO(r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.out.empty());
    const std::string expected_start = "twinraster: " + file.string() + ": " + c.where + ": ";
    REQUIRE(r.err.rfind(expected_start, 0) == 0);
    REQUIRE(r.err.find(c.problem) != std::string::npos);
    REQUIRE(std::count(r.err.begin(), r.err.end(), '\n') == 1);  // one line, no stack of errors
  }
}

TEST_CASE("A missing file, a directory or a device is bad input too", "[bad-input]") {
  const test::TempDir dir;
  const std::vector<std::pair<std::filesystem::path, std::string>> cases = {
      {dir / "no-such-scene.json", "no such file"},
      {dir.path(), "is a directory"},
      {"/dev/zero", "not a regular file"},
  };
  for (const auto& [path, problem] : cases) {
    const test::CliResult r = test::RunCli({"explain", path.string()});
    INFO(r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.err.rfind("twinraster: " + path.string() + ": (file): " + problem, 0) == 0);
  }
}
