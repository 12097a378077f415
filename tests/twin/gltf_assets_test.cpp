// The glTF files Debian's assimp-testmodels ships, which no one here wrote: each is in the table
// of docs/gltf-assets.md and does what its row says. Refused: a SceneError with the row's words.
// Renders: lavapipe == twin bit for bit, SwiftShader == twin with SwiftShader's rules, and the
// verifier does not fail lavapipe's image. Drawn at 320 x 240 (--size), so that every camera's
// aspect ratio meets a canvas of another shape.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "run/backend_draws.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_error.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "twin_rules/twin_rules.hpp"
#include "twin_support.hpp"
#include "verify/verifier.hpp"

#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

using namespace twinraster;

namespace {

const std::filesystem::path kModels = "/usr/share/assimp/models";

struct AssetRow {
  bool renders = false;
  std::string why;  // for a refusal, words its message must contain
};

// The rows of docs/gltf-assets.md's table: | path | renders or refused | why |.
std::map<std::string, AssetRow> AssetTable() {
  std::ifstream in(test::SourcePath("docs/gltf-assets.md"));
  std::map<std::string, AssetRow> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| glTF", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream cells_in(line.substr(1));
    for (std::string cell; std::getline(cells_in, cell, '|');) {
      cell.erase(0, cell.find_first_not_of(' '));
      cell.erase(cell.find_last_not_of(' ') + 1);
      cells.push_back(cell);
    }
    if (cells.size() < 3 || (cells[1] != "renders" && cells[1] != "refused")) {
      throw std::runtime_error("docs/gltf-assets.md: a row that is not | path | renders or refused | why |: " + line);
    }
    rows[cells[0]] = AssetRow{cells[1] == "renders", cells[2]};
  }
  return rows;
}

// Every .gltf and .glb under glTF/ and glTF2/, relative to kModels, sorted.
std::vector<std::string> ShippedFiles() {
  std::vector<std::string> files;
  for (const char* folder : {"glTF", "glTF2"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(kModels / folder)) {
      const std::string ext = entry.path().extension().string();
      if (ext == ".gltf" || ext == ".glb") files.push_back(std::filesystem::relative(entry.path(), kModels).string());
    }
  }
  std::sort(files.begin(), files.end());
  // Debian 12 ships 53, Debian 13 54: fewer means the package is missing or changed.
  if (files.size() < 53) throw std::runtime_error("assimp-testmodels: " + std::to_string(files.size()) + " glTF files");
  return files;
}

Scene Load(const std::string& file) {
  return LoadSceneOrObj(kModels / file, SceneChoice{std::nullopt, std::nullopt, CanvasSize{320, 240}});
}

}  // namespace

TEST_CASE("Every glTF file of assimp-testmodels is in docs/gltf-assets.md, refused with its row's reason or read") {
  const std::map<std::string, AssetRow> table = AssetTable();
  std::size_t refused = 0, read = 0;
  for (const std::string& file : ShippedFiles()) {
    INFO(file);
    const auto row = table.find(file);
    REQUIRE(row != table.end());
    if (row->second.renders) {
      REQUIRE_NOTHROW(Load(file));
      ++read;
      continue;
    }
    try {
      Load(file);
      FAIL("read, but the table says refused: " << row->second.why);
    } catch (const SceneError& e) {
      CHECK_THAT(e.what(), HasSubstring(row->second.why));
      CHECK(std::string(e.what()).find('\n') == std::string::npos);
      ++refused;
    }
  }
  // Every row is a file this release ships, but Debian 13's additions on Debian 12.
  std::size_t listed_here = 0;
  for (const auto& [file, row] : table) {
    const bool here = std::filesystem::exists(kModels / file);
    CHECK((here || row.why.find("Debian 13 only") != std::string::npos));
    listed_here += here;
  }
  CHECK(refused + read == listed_here);
  CHECK(refused == 29);
  CHECK(read >= 24);
}

TEST_CASE(
    "Every assimp-testmodels glTF file that renders: lavapipe == twin, SwiftShader == twin, and verify passes it "
    "or the table says why it is inconclusive") {
  const std::map<std::string, AssetRow> table = AssetTable();
  const twin_rules::TwinRules swiftshader =
      twin_rules::ChooseTwinRules(run::FactsOf(test::SharedSwiftShader().Device()), twin_rules::DetectCpuPath());
  REQUIRE(swiftshader.exact);
  std::size_t judged = 0;
  for (const std::string& file : ShippedFiles()) {
    if (!table.at(file).renders) continue;
    INFO(file);
    const Scene scene = Load(file);
    const DrawList list = BuildDrawList(scene);
    const test::TwinResult lavapipe = test::RenderTwins(list);
    INFO(lavapipe.Describe());
    REQUIRE(lavapipe.Equal());
    test::RequireNoValidationMessages();

    cpu::CpuOptions options;
    options.rules = swiftshader.rules;
    const Comparison swift = CompareImages(test::SharedSwiftShader().Render(list), cpu::RenderOnCpu(list, options));
    INFO("SwiftShader: " << swift.differing_pixels << " differing pixels");
    REQUIRE(swift.Equal());
    REQUIRE(test::SharedSwiftShader().ValidationMessages().empty());

    // lavapipe's rules: 8 sub-pixel bits, strict lines.
    const verify::Verification judged_image =
        verify::VerifyImage(scene, list, lavapipe.gpu, verify::VerifyOptions{8, true});
    INFO(verify::JudgementName(verify::JudgementOf(judged_image)));
    REQUIRE(verify::JudgementOf(judged_image) != verify::Judgement::kFailed);
    // An inconclusive judgement is not a pass: the table must say so, and only then.
    const bool inconclusive = verify::JudgementOf(judged_image) == verify::Judgement::kInconclusive;
    CHECK(inconclusive == (table.at(file).why.find("verify is inconclusive") != std::string::npos));
    ++judged;
  }
  CHECK(judged >= 24);
}
