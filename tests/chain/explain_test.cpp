// `twinraster explain`, run as a user runs it: the text names the chapter's matrices and traces
// one vertex per instance unless asked for all, --html prints only where the page went, and the
// JSON trace agrees with the chapter's canvas formula and with Vulkan's framebuffer convention.
#include "support/catch.hpp"
#include "support/negative_zero.hpp"
#include "support/test_support.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <vector>

using namespace twinraster;

TEST_CASE("explain prints the chain with the chapter's names", "[explain]") {
  const test::CliResult r = test::RunCli({"explain", test::SourcePath("scenes/cgfs-transforms.json").string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  for (const char* name : {"M_Projection", "M_Camera = C_R⁻¹ · C_T⁻¹", "M_Model = I_T · I_R · I_S",
                           "F = M_Projection · M_Camera · M_Model", "ViewportToCanvas", "framebuffer"}) {
    INFO(name);
    REQUIRE(r.out.find(name) != std::string::npos);
  }
  REQUIRE(r.err.empty());
}

TEST_CASE("explain shows a traced vertex's own colour, unlit as interpolated and lit as the base its light scales",
          "[explain][vertex-colours]") {
  const test::CliResult unlit = test::RunCli({"explain", test::SourcePath("scenes/vertex-colours.json").string()});
  INFO(unlit.err);
  REQUIRE(unlit.exit_code == 0);
  // Vertex 0 of the cube is white, vertex 1 cyan: instance 0 traces vertex 0 (the first inside).
  CHECK_THAT(unlit.out, HasSubstring("colour       (255, 255, 255) / 255, the vertex colour, interpolated"));
  const test::CliResult lit = test::RunCli(
      {"explain", test::SourcePath("scenes/lit-vertex-colours.json").string(), "--instance", "0", "--vertex", "1"});
  INFO(lit.err);
  REQUIRE(lit.exit_code == 0);
  CHECK_THAT(lit.out, HasSubstring("colour = vertex colour (40, 200, 220) / 255 · min(I, 1)"));
  // Without vertex colours the triangle's colour is the base, as before.
  const test::CliResult plain = test::RunCli({"explain", test::SourcePath("scenes/lit-mixed.json").string()});
  REQUIRE(plain.exit_code == 0);
  CHECK_THAT(plain.out, HasSubstring("colour = base ("));
  CHECK(plain.out.find("vertex colour") == std::string::npos);
}

TEST_CASE(
    "explain --json: canvas equals x·d·Cw/(z·Vw) (orthographic x·Cw/Vw), framebuffer is the canvas moved to Vulkan's "
    "origin",
    "[explain]") {
  for (const auto& file : test::ShippedScenes()) {
    INFO(file.string());
    const test::CliResult r = test::RunCli({"explain", file.string(), "--json"});
    REQUIRE(r.exit_code == 0);
    const auto j = nlohmann::json::parse(r.out);
    REQUIRE(j.at("format") == "twinraster.explain/3");
    REQUIRE(j.at("projection_matrix").size() == 4);
    REQUIRE(j.at("camera_matrix").at(3).size() == 4);
    const double cw = j["canvas"]["width"], ch = j["canvas"]["height"];
    const double vw = j["viewport"]["width"], vh = j["viewport"]["height"], d = j["viewport"]["distance"];
    const bool orthographic = j["viewport"]["projection"] == "orthographic";
    REQUIRE(j.at(orthographic ? "perspective_matrix" : "orthographic_matrix").is_null());
    REQUIRE(j.at(orthographic ? "orthographic_matrix" : "perspective_matrix").size() == 4);
    for (const auto& instance : j.at("instances")) {
      REQUIRE(instance.at("model_matrix").size() == 4);
      REQUIRE(instance.at("mvp").size() == 4);
      for (const auto& v : instance.at("vertices")) {
        const double x = v["camera"][0], y = v["camera"][1], z = v["camera"][2];
        const double cx = v["canvas"][0], cy = v["canvas"][1];
        const double expected_x = orthographic ? x * cw / vw : x * d * cw / (z * vw);
        const double expected_y = orthographic ? y * ch / vh : y * d * ch / (z * vh);
        const double scale = 1 + std::abs(expected_x) + std::abs(expected_y);
        REQUIRE(cx == Approx(expected_x).margin(1e-12 * scale));
        REQUIRE(cy == Approx(expected_y).margin(1e-12 * scale));
        REQUIRE(double(v["framebuffer"][0]) == Approx(cx + cw / 2).margin(1e-12 * scale));
        REQUIRE(double(v["framebuffer"][1]) == Approx(ch / 2 - cy).margin(1e-12 * scale));
        for (const char* key : {"object", "world", "clip", "ndc"}) REQUIRE(v.contains(key));
      }
    }
  }
}

TEST_CASE("explain --instance and --vertex select one trace, and reject indices that don't exist", "[explain]") {
  const std::string scene = test::SourcePath("scenes/cgfs-transforms.json").string();
  const test::CliResult one = test::RunCli({"explain", scene, "--json", "--instance", "1", "--vertex", "6"});
  REQUIRE(one.exit_code == 0);
  const auto j = nlohmann::json::parse(one.out);
  REQUIRE(j["instances"].size() == 1);
  REQUIRE(j["instances"][0]["index"] == 1);
  REQUIRE(j["instances"][0]["vertices"].size() == 1);
  REQUIRE(j["instances"][0]["vertices"][0]["object"] == nlohmann::json::array({-1, -1, -1}));

  const test::CliResult bad_instance = test::RunCli({"explain", scene, "--instance", "2"});
  REQUIRE(bad_instance.exit_code == 2);
  REQUIRE(bad_instance.err.find("--instance 2: the scene has 2 instances: give 0 to 1") != std::string::npos);
  const test::CliResult bad_vertex = test::RunCli({"explain", scene, "--vertex", "8"});
  REQUIRE(bad_vertex.exit_code == 2);
  REQUIRE(bad_vertex.err.find("has 8 vertices: give 0 to 7") != std::string::npos);
  const test::CliResult not_a_number = test::RunCli({"explain", scene, "--vertex", "x"});
  REQUIRE(not_a_number.exit_code == 2);
  const test::CliResult unknown_option = test::RunCli({"explain", scene, "--verbose"});
  REQUIRE(unknown_option.exit_code == 2);
  REQUIRE(unknown_option.err.rfind("twinraster explain: unknown option --verbose", 0) == 0);
}

TEST_CASE("explain - reads the scene from standard input, named <stdin>", "[explain]") {
  const std::string text = test::ReadFile(test::SourcePath("scenes/cgfs-transforms.json"));
  const test::CliResult from_file =
      test::RunCli({"explain", test::SourcePath("scenes/cgfs-transforms.json").string(), "--json"});
  const test::CliResult from_stdin = test::RunCliWithInput({"explain", "-", "--json"}, text);
  INFO(from_stdin.err);
  REQUIRE(from_stdin.exit_code == 0);
  auto a = nlohmann::json::parse(from_file.out), b = nlohmann::json::parse(from_stdin.out);
  REQUIRE(b["scene"] == "<stdin>");
  a.erase("scene"), b.erase("scene");
  REQUIRE(a == b);  // everything else is the same chain

  const test::CliResult bad = test::RunCliWithInput({"explain", "-"}, "{\"canvs\": {}}");
  REQUIRE(bad.exit_code == 2);
  REQUIRE(bad.err.rfind("twinraster: <stdin>: ", 0) == 0);
  REQUIRE(std::count(bad.err.begin(), bad.err.end(), '\n') == 1);
}

namespace {

// The vertex indices the text traces, in order ("  vertex 3" lines).
std::vector<std::size_t> TracedVertices(const std::string& text) {
  static const std::regex line("\n  vertex ([0-9]+)");
  std::vector<std::size_t> found;
  for (auto it = std::sregex_iterator(text.begin(), text.end(), line); it != std::sregex_iterator(); ++it) {
    found.push_back(std::stoul((*it)[1].str()));
  }
  return found;
}

}  // namespace

TEST_CASE("explain traces one vertex per instance by default: the first inside the clip volume", "[explain]") {
  for (const char* name : {"cgfs-transforms.json", "lit-gouraud.json", "catlike-grid.json"}) {
    const std::string scene = test::SourcePath(std::string("scenes/") + name).string();
    INFO(scene);
    const test::CliResult text = test::RunCli({"explain", scene});
    const test::CliResult json = test::RunCli({"explain", scene, "--json"});
    REQUIRE(text.exit_code == 0);
    REQUIRE(json.exit_code == 0);
    std::vector<std::size_t> first_inside;
    const auto j = nlohmann::json::parse(json.out);
    for (const auto& instance : j.at("instances")) {
      const auto& vertices = instance.at("vertices");
      const auto inside = std::find_if(vertices.begin(), vertices.end(),
                                       [](const auto& v) { return v.at("inside_clip_volume") == true; });
      first_inside.push_back(inside == vertices.end() ? 0 : inside->at("index").get<std::size_t>());
    }
    CHECK(TracedVertices(text.out) == first_inside);
  }
}

TEST_CASE("explain --all-vertices traces every vertex of each instance, --vertex picks one, and not both at once",
          "[explain]") {
  const std::string scene = test::SourcePath("scenes/cgfs-transforms.json").string();
  const test::CliResult all = test::RunCli({"explain", scene, "--all-vertices"});
  REQUIRE(all.exit_code == 0);
  const std::vector<std::size_t> cube = {0, 1, 2, 3, 4, 5, 6, 7};
  std::vector<std::size_t> both = cube;
  both.insert(both.end(), cube.begin(), cube.end());
  CHECK(TracedVertices(all.out) == both);
  CHECK(all.out.find("traced: vertex") == std::string::npos);
  const test::CliResult one = test::RunCli({"explain", scene, "--vertex", "6"});
  REQUIRE(one.exit_code == 0);
  CHECK(TracedVertices(one.out) == std::vector<std::size_t>{6, 6});
  // The JSON traces every vertex by default, so --all-vertices changes nothing there.
  const test::CliResult json = test::RunCli({"explain", scene, "--json"});
  CHECK(test::RunCli({"explain", scene, "--json", "--all-vertices"}).out == json.out);
  const test::CliResult conflict = test::RunCli({"explain", scene, "--vertex", "6", "--all-vertices"});
  CHECK(conflict.exit_code == 2);
  CHECK_THAT(conflict.err, HasSubstring("--all-vertices"));
}

TEST_CASE("explain --html writes the page and prints one line saying where, or with --json the JSON alone",
          "[explain]") {
  const test::TempDir dir;
  const std::string scene = test::SourcePath("scenes/lit-gouraud.json").string();
  const std::string page = (dir / "chain page.html").string();
  const test::CliResult r = test::RunCli({"explain", scene, "--html", page});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  CHECK(r.out == "wrote " + page + "\n");
  // Nothing else, but in a build without the browser module the one line that says why the page
  // is static (tests/moving_page/ checks its words).
  CHECK((r.err.empty() || r.err.rfind("note: the page does not move: this build has no browser module", 0) == 0));
  CHECK(test::ReadFile(page).rfind("<!DOCTYPE html>", 0) == 0);

  const test::CliResult with_json = test::RunCli({"explain", scene, "--html", page, "--json", "--vertex", "3"});
  REQUIRE(with_json.exit_code == 0);
  CHECK(with_json.out == test::RunCli({"explain", scene, "--json", "--vertex", "3"}).out);
  CHECK_THAT(test::ReadFile(page), HasSubstring("takes vertex 3 of instance 0"));

  const std::string never = (dir / "never.html").string();
  const test::CliResult bad = test::RunCli({"explain", scene, "--html", never, "--vertex", "1000000"});
  CHECK(bad.exit_code == 2);
  CHECK(bad.out.empty());
  CHECK_FALSE(std::filesystem::exists(never));
  // A scene without instances has no chain to draw: a usage error, not a crash.
  auto empty = nlohmann::json::parse(test::ReadFile(test::SourcePath("scenes/cgfs-transforms.json")));
  empty["instances"] = nlohmann::json::array();
  const test::CliResult nothing = test::RunCliWithInput({"explain", "-", "--html", never}, empty.dump());
  CHECK(nothing.exit_code == 2);
  CHECK(nothing.err.rfind("twinraster explain: --html: the scene has no instance to draw", 0) == 0);
  CHECK_FALSE(std::filesystem::exists(never));
}

TEST_CASE("explain's text and page never show -0, though the JSON has negative zeros", "[explain]") {
  const test::TempDir dir;
  // Scenes whose matrices or traces hold a -0.0: a normal matrix of a scale, mirrored and zero scales.
  for (const char* name : {"lit-gouraud.json", "hard/lit-mirror-scales.json", "hard/zero-negative-scale.json"}) {
    const std::string scene = test::SourcePath(std::string("scenes/") + name).string();
    INFO(scene);
    const test::CliResult json = test::RunCli({"explain", scene, "--json"});
    REQUIRE(json.exit_code == 0);
    REQUIRE(json.out.find("-0.0") != std::string::npos);
    const test::CliResult text = test::RunCli({"explain", scene, "--all-vertices"});
    REQUIRE(text.exit_code == 0);
    CHECK_FALSE(test::HasNegativeZero(text.out));
    const std::string page = (dir / "page.html").string();
    REQUIRE(test::RunCli({"explain", scene, "--html", page}).exit_code == 0);
    CHECK_FALSE(test::HasNegativeZero(test::ReadFile(page)));
  }
}
