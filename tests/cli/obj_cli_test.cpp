// `twinraster render mesh.obj` and `explain mesh.obj`: an OBJ file on its own, as tinyrenderer's
// command line takes one.
#include "files/png_file.hpp"
#include "image/image.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/test_support.hpp"

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

using namespace twinraster;

namespace {

// An octahedron around (0, 0, 10), far from the origin, so that only a framing camera sees it whole.
const std::string kOctahedron =
    "v 1 0 10\nv -1 0 10\nv 0 1 10\nv 0 -1 10\nv 0 0 11\nv 0 0 9\n"
    "f 1 3 5\nf 3 2 5\nf 2 4 5\nf 4 1 5\nf 3 1 6\nf 2 3 6\nf 4 2 6\nf 1 4 6\n";
const Rgb8 kBackground{40, 40, 48};

}  // namespace

TEST_CASE("render mesh.obj --backend cpu writes the framed mesh as a PNG", "[cli][obj]") {
  const test::TempDir dir;
  test::WriteFile(dir / "octahedron.obj", kOctahedron);
  const auto out = dir / "out.png";
  const test::CliResult r =
      test::RunCli({"render", (dir / "octahedron.obj").string(), "--backend", "cpu", "-o", out.string()});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("1 instance, 8 triangles, 800 x 800") != std::string::npos);
  const Image image = files::ReadPng(out);
  REQUIRE(image.width == 800);
  REQUIRE(image.height == 800);
  // The mesh covers the centre, and its corners are background.
  const auto at = [&](std::size_t x, std::size_t y) {
    const std::size_t i = 4 * (y * image.width + x);
    return Rgb8{image.rgba[i], image.rgba[i + 1], image.rgba[i + 2]};
  };
  REQUIRE(!(at(400, 400) == kBackground));
  REQUIRE(at(5, 5) == kBackground);
  REQUIRE(at(794, 794) == kBackground);
  const std::size_t painted = test::CountNotColour(image, kBackground);
  REQUIRE(painted > 800 * 800 / 10);
  REQUIRE(painted < 800 * 800 / 2);
}

TEST_CASE("explain mesh.obj prints the chain of the scene render gives it", "[cli][obj]") {
  const test::TempDir dir;
  test::WriteFile(dir / "octahedron.obj", kOctahedron);
  const test::CliResult r =
      test::RunCli({"explain", (dir / "octahedron.obj").string(), "--instance", "0", "--vertex", "0"});
  INFO(r.err);
  REQUIRE(r.exit_code == 0);
  REQUIRE(r.out.find("Scene \"octahedron\": canvas Cw x Ch = 800 x 800 px") != std::string::npos);
  REQUIRE(r.out.find("M_Model") != std::string::npos);
}

TEST_CASE("A bad OBJ file on the command line: one line naming it and the line, exit code 2", "[cli][obj][bad-input]") {
  const test::TempDir dir;
  const auto bad = dir / "bad.obj";
  test::WriteFile(bad, "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n");
  const std::vector<std::vector<std::string>> runs = {{"render", bad.string(), "--backend", "cpu"},
                                                      {"explain", bad.string()}};
  for (const auto& args : runs) {
    INFO(args[0]);
    const test::CliResult r = test::RunCli(args);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.err ==
            "twinraster: " + bad.string() +
                ": line 5: f: corner 3 \"4\": vertex index 4 is out of range: the file has 3 vertices (v lines)\n");
  }
  const test::CliResult missing = test::RunCli({"render", (dir / "none.obj").string(), "--backend", "cpu"});
  REQUIRE(missing.exit_code == 2);
  REQUIRE(missing.err == "twinraster: " + (dir / "none.obj").string() + ": (file): no such file\n");
}

TEST_CASE("render and explain --help say that SCENE may be an OBJ file", "[cli][obj]") {
  for (const char* command : {"render", "explain"}) {
    INFO(command);
    const test::CliResult r = test::RunCli({command, "--help"});
    REQUIRE(r.exit_code == 0);
    REQUIRE(r.out.find("OBJ mesh") != std::string::npos);
    REQUIRE(r.out.find(".obj") != std::string::npos);
  }
}

TEST_CASE("An OBJ or glTF file piped to SCENE - is named as such: - reads a JSON scene only", "[cli][obj][bad-input]") {
  const test::TempDir dir;
  const std::string glb("glTF\x02\0\0\0\x14\0\0\0\0\0\0\0JSON", 20);
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"# an octahedron\n" + kOctahedron, "; this looks like an OBJ mesh: give its file name instead)\n"},
      {kOctahedron, "; this looks like an OBJ mesh: give its file name instead)\n"},
      {glb, "; this looks like a binary glTF file (.glb): give its file name instead)\n"},
      {"canvas: 600", " (- reads a JSON scene file only)\n"},
  };
  for (const auto& [input, ending] : cases) {
    INFO(input);
    const test::CliResult r = test::RunCliWithInput({"render", "-", "-o", (dir / "o.png").string()}, input);
    INFO(r.err);
    REQUIRE(r.exit_code == 2);
    REQUIRE(r.err.rfind("twinraster: <stdin>: line 1, column ", 0) == 0);
    REQUIRE(r.err.find("(- reads a JSON scene file only") != std::string::npos);
    REQUIRE(r.err.ends_with(ending));
    REQUIRE(std::count(r.err.begin(), r.err.end(), '\n') == 1);
  }
  // A JSON scene with a syntax error is JSON: its message needs no hint.
  const test::CliResult json = test::RunCliWithInput({"render", "-", "-o", (dir / "o.png").string()}, "{\"canvas\": ");
  REQUIRE(json.exit_code == 2);
  REQUIRE(json.err.find("reads a JSON scene") == std::string::npos);
}
