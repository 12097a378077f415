// The verifier on vertex colours: each covered pixel may take the colours a conformant
// implementation may interpolate there from the corners' colours (as for Gouraud light), so the
// twin's images pass under lavapipe's and SwiftShader's rules, unlit, flat and Gouraud, and an
// image with wrong vertex colours, or none, fails.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "run_report/verify_report.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/lit_scene.hpp"
#include "support/test_support.hpp"
#include "twin_rules/twin_rules.hpp"
#include "verify/verifier.hpp"

#include <string>
#include <utility>
#include <vector>

using namespace twinraster;

namespace {

// The twin's rules for each device it copies, with the subpixel bits the device reports.
struct Device {
  std::string name;
  cpu::RasterRules rules;
  int bits = 8;
};
std::vector<Device> Devices() {
  const twin_rules::KnownSwiftShader& swiftshader = twin_rules::SwiftShaderRow();
  return {{"lavapipe", cpu::CpuOptions{}.rules, 8},
          {"SwiftShader", swiftshader.rules, static_cast<int>(swiftshader.subpixel_bits)}};
}

verify::Verification Judge(const Scene& scene, const DrawList& list, const Image& image, int bits) {
  return verify::VerifyImage(scene, list, image, {.subpixel_bits = bits, .strict_lines = true});
}

std::vector<std::pair<std::string, Scene>> Scenes() {
  std::vector<std::pair<std::string, Scene>> scenes;
  for (const char* file : {"scenes/vertex-colours.json", "scenes/lit-vertex-colours.json"})
    scenes.emplace_back(file, LoadScene(test::SourcePath(file)));
  for (std::uint32_t seed = 1; seed <= 30; ++seed)
    scenes.emplace_back("random seed " + std::to_string(seed), test::RandomVertexColourScene(seed));
  return scenes;
}

// The scene with every vertex colour's red and blue swapped: the picture a driver that read the
// attribute's bytes the wrong way round would draw.
Scene SwappedRedBlue(Scene scene) {
  for (Model& model : scene.models) {
    for (Rgb8& c : model.vertex_colours) std::swap(c.r, c.b);
  }
  return scene;
}

}  // namespace

TEST_CASE("verify: the twin's vertex-coloured images pass under lavapipe's and SwiftShader's rules",
          "[verify][vertex-colours]") {
  int judged = 0;
  for (const Device& device : Devices()) {
    for (const auto& [name, scene] : Scenes()) {
      const DrawList list = BuildDrawList(scene);
      const verify::Verification v =
          Judge(scene, list, cpu::RenderOnCpu(list, cpu::CpuOptions{.rules = device.rules}), device.bits);
      INFO(device.name << ", " << name << ": " << run_report::VerificationText(v));
      CHECK(v.NoViolations());
      ++judged;
    }
  }
  CHECK(judged == 2 * 32);
}

TEST_CASE("verify: wrong vertex colours, or none, fail", "[verify][vertex-colours]") {
  for (const char* file : {"scenes/vertex-colours.json", "scenes/lit-vertex-colours.json"}) {
    const Scene scene = LoadScene(test::SourcePath(file));
    const DrawList list = BuildDrawList(scene);
    INFO(file);
    // Red and blue swapped in every vertex colour.
    const Image swapped = cpu::RenderOnCpu(BuildDrawList(SwappedRedBlue(scene)));
    const verify::Verification v = Judge(scene, list, swapped, 8);
    INFO(run_report::VerificationText(v));
    CHECK(v.violations > 1000);
    // The triangles' own colours instead of the vertices' (a driver that ignored the attribute).
    DrawList flat = list;
    for (DrawMesh& mesh : flat.meshes) mesh.vertex_colours.clear();
    const verify::Verification f = Judge(scene, list, cpu::RenderOnCpu(flat), 8);
    INFO(run_report::VerificationText(f));
    CHECK(f.violations > 1000);
    // One pixel inside a face, certain, with its green pushed 40 away.
    Image image = cpu::RenderOnCpu(list);
    const verify::Verification clean = Judge(scene, list, image, 8);
    REQUIRE(clean.NoViolations());
    std::size_t at = 0;
    const std::size_t centre = std::size_t{list.height / 2} * list.width + list.width / 2;
    for (std::size_t i = centre; i < clean.pixels.size(); ++i) {
      const Rgb8 c{image.rgba[4 * i], image.rgba[4 * i + 1], image.rgba[4 * i + 2]};
      if (clean.pixels[i] == verify::PixelClass::kCertain && !(c == scene.canvas.background)) {
        at = i;
        break;
      }
    }
    REQUIRE(at != 0);
    std::uint8_t& green = image.rgba[4 * at + 1];
    green = static_cast<std::uint8_t>(green < 128 ? green + 40 : green - 40);
    const verify::Verification one = Judge(scene, list, image, 8);
    INFO(run_report::VerificationText(one));
    CHECK(one.violations == 1);
  }
}
