// `twinraster explain`, run as a user runs it: the text names the chapter's matrices, and the JSON
// trace agrees with the chapter's canvas formula and with Vulkan's framebuffer convention.
#include "support/test_support.hpp"

#include "support/catch.hpp"
#include <nlohmann/json.hpp>

#include <algorithm>

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

TEST_CASE("explain --json: canvas equals x·d·Cw/(z·Vw) (orthographic x·Cw/Vw), framebuffer is the canvas moved to Vulkan's origin", "[explain]") {
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
  REQUIRE(bad_instance.err.find("--instance 2: the scene has 2 instance(s)") != std::string::npos);
  const test::CliResult bad_vertex = test::RunCli({"explain", scene, "--vertex", "8"});
  REQUIRE(bad_vertex.exit_code == 2);
  REQUIRE(bad_vertex.err.find("has 8 vertices") != std::string::npos);
  const test::CliResult not_a_number = test::RunCli({"explain", scene, "--vertex", "x"});
  REQUIRE(not_a_number.exit_code == 2);
  const test::CliResult unknown_option = test::RunCli({"explain", scene, "--verbose"});
  REQUIRE(unknown_option.exit_code == 2);
  REQUIRE(unknown_option.err.rfind("twinraster explain: unknown option --verbose", 0) == 0);
}

TEST_CASE("explain - reads the scene from standard input, named <stdin>", "[explain]") {
  const std::string text = test::ReadFile(test::SourcePath("scenes/cgfs-transforms.json"));
  const test::CliResult from_file = test::RunCli({"explain", test::SourcePath("scenes/cgfs-transforms.json").string(), "--json"});
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
