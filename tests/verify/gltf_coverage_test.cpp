// verify --coverage (run::JudgeCoverage) on the shipped glTF scenes (scenes/gltf/): the twin's image
// under an engine's own shading passes, and the image of each classic glTF import bug fails. Each
// bug is a deliberately wrong composer of the GltfDocument into the Scene (the node chain built
// here from doc.nodes, or the camera's lens changed), drawn by the twin, its covered pixels
// recoloured with noise so that only coverage can tell, and judged against the correct scene.
#include "chain/draw_list.hpp"
#include "chain/matrices.hpp"
#include "cpu/cpu_renderer.hpp"
#include "engine_shading.hpp"
#include "run/judge_coverage.hpp"
#include "scene/gltf_document.hpp"
#include "scene/gltf_scene.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "verify/verifier.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace twinraster;
using test::Is;
using test::Recolour;
using test::Shade;

namespace {

// Every glTF scene the repository ships; the first case checks that scenes/gltf/ holds no other.
const std::vector<std::string> kScenes = {"scenes/gltf/arm.gltf", "scenes/gltf/strips.gltf",
                                          "scenes/gltf/colonnade.glb"};

struct Loaded {
  GltfDocument doc;
  Scene scene;
};

Loaded Load(const std::string& file) {
  const std::filesystem::path path = test::SourcePath(file);
  Loaded l{ReadGltf(path), {}};
  l.scene = GltfScene(l.doc, SceneChoice{}, path.stem().string());
  return l;
}

Image Twin(const Scene& scene) { return cpu::RenderOnCpu(BuildDrawList(scene)); }

// --- The composers: a node's local matrix and an instance's chain, written here from doc.nodes
// (not by the reader's LocalMatrix), right or with one bug.

enum class Bug {
  kNone,
  kScaleRotationTranslation,  // the node's S · R · T instead of T · R · S
  kMatrixRowMajor,            // `matrix` read row by row: the file's matrix transposed
  kNoMirror,                  // glTF's right-handed world drawn without the z mirror
  kMirrorInside,              // the mirror applied on the wrong side: N_root ... N_node · mirror
  kParentDropped,             // each mesh node's local matrix used as its world matrix
};

// glTF's quaternion (x, y, z, w) as a rotation matrix, normalised first as exporters round them.
glm::dmat4 Quaternion(glm::dvec4 q) {
  q = glm::normalize(q);
  const double x = q.x, y = q.y, z = q.z, w = q.w;
  const double rows[4][4] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w), 0},
                             {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w), 0},
                             {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y), 0},
                             {0, 0, 0, 1}};
  return FromRows(rows);
}

glm::dmat4 Local(const GltfNode& n, Bug bug) {
  if (n.has_matrix) return bug == Bug::kMatrixRowMajor ? glm::transpose(n.matrix) : n.matrix;
  const glm::dmat4 t = Translation(n.translation), r = Quaternion(n.rotation), s = Scale(n.scale);
  return bug == Bug::kScaleRotationTranslation ? s * r * t : t * r * s;
}

TransformStep MatrixStep(const glm::dmat4& m) {
  TransformStep step;
  step.kind = TransformStep::Kind::kMatrix;
  step.matrix = m;
  return step;
}

// The steps of one mesh node's instance, applied first to last: its local matrix, its parents' up
// to the root, the chapter's z mirror.
std::vector<TransformStep> Chain(const GltfDocument& doc, std::size_t node, Bug bug) {
  std::vector<TransformStep> steps;
  TransformStep mirror;
  mirror.kind = TransformStep::Kind::kScale;
  mirror.vector = {1, 1, -1};
  if (bug == Bug::kMirrorInside) steps.push_back(mirror);
  for (std::optional<std::size_t> at = node; at; at = doc.nodes[*at].parent) {
    steps.push_back(MatrixStep(Local(doc.nodes[*at], bug)));
    if (bug == Bug::kParentDropped) break;
  }
  if (bug != Bug::kNoMirror && bug != Bug::kMirrorInside) steps.push_back(mirror);
  return steps;
}

// The mesh nodes of the document's default scene, depth first in the file's order, once per
// primitive: the order GltfScene makes its instances in (every primitive of these files draws).
std::vector<std::size_t> InstanceNodes(const GltfDocument& doc) {
  std::vector<std::size_t> out, stack;
  const std::vector<std::size_t>& roots = doc.scenes.at(doc.default_scene.value_or(0)).nodes;
  stack.assign(roots.rbegin(), roots.rend());
  while (!stack.empty()) {
    const std::size_t n = stack.back();
    stack.pop_back();
    if (doc.nodes[n].mesh) out.insert(out.end(), doc.meshes[*doc.nodes[n].mesh].primitives.size(), n);
    stack.insert(stack.end(), doc.nodes[n].children.rbegin(), doc.nodes[n].children.rend());
  }
  return out;
}

// The correct scene with every instance's chain composed here, with `bug`.
Scene Composed(const Loaded& l, Bug bug) {
  Scene s = l.scene;
  const std::vector<std::size_t> nodes = InstanceNodes(l.doc);
  REQUIRE(nodes.size() == s.instances.size());
  for (std::size_t i = 0; i < nodes.size(); ++i) {
    s.instances[i].transform = {};
    s.instances[i].transform.steps = std::make_shared<const std::vector<TransformStep>>(Chain(l.doc, nodes[i], bug));
  }
  return s;
}

// The camera's lens 1 % wider: a perspective yfov x 1.01, an orthographic xmag and ymag x 1.01
// (its field of view); the scene rebuilt by GltfScene at the same canvas.
Scene WiderLens(const Loaded& l) {
  GltfDocument doc = l.doc;
  for (GltfCamera& c : doc.cameras) {
    c.yfov *= 1.01;
    c.xmag *= 1.01;
    c.ymag *= 1.01;
  }
  return GltfScene(doc,
                   SceneChoice{std::nullopt, std::nullopt, CanvasSize{l.scene.canvas.width, l.scene.canvas.height}},
                   l.scene.name);
}

struct Variant {
  std::string name;
  std::function<Scene(const Loaded&)> make;
};

const std::vector<Variant>& Variants() {
  static const std::vector<Variant> variants = {
      {"T·R·S applied as S·R·T", [](const Loaded& l) { return Composed(l, Bug::kScaleRotationTranslation); }},
      {"node matrix read row-major (transposed)", [](const Loaded& l) { return Composed(l, Bug::kMatrixRowMajor); }},
      {"handedness: no z mirror", [](const Loaded& l) { return Composed(l, Bug::kNoMirror); }},
      {"handedness: mirror on the wrong side (N_root ... N_node · mirror)",
       [](const Loaded& l) { return Composed(l, Bug::kMirrorInside); }},
      {"field of view 1 % wide (yfov x 1.01; orthographic xmag, ymag x 1.01)", WiderLens},
      {"aspect ratio ignored (square viewport on the camera's canvas)",
       [](const Loaded& l) {
         Scene s = l.scene;
         s.viewport.width = s.viewport.height;
         return s;
       }},
      {"child not composed with its parent (local matrix as world)",
       [](const Loaded& l) { return Composed(l, Bug::kParentDropped); }},
  };
  return variants;
}

// Each test case writes its own file: CTest runs them in parallel, and one file shared by two
// of them came out with their rows interleaved.
void AppendTable(const std::string& file, const std::string& line) {
  std::ofstream out(std::filesystem::path(TWINRASTER_BINARY_DIR) / file, std::ios::app);
  out << line << "\n";
}

}  // namespace

TEST_CASE("glTF coverage: scenes/gltf holds the shipped glTF scenes, each with every feature a defect needs",
          "[verify][coverage][gltf]") {
  std::size_t files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(test::SourcePath("scenes/gltf"))) {
    if (!IsGltfName(entry.path())) continue;
    const std::string relative = "scenes/gltf/" + entry.path().filename().string();
    INFO(relative);
    CHECK(std::find(kScenes.begin(), kScenes.end(), relative) != kScenes.end());
    ++files;
  }
  CHECK(files == kScenes.size());
  for (const std::string& file : kScenes) {
    INFO(file);
    const Loaded l = Load(file);
    std::size_t matrices = 0, turned_scaled = 0, under_parent = 0;
    for (const GltfNode& n : l.doc.nodes) {
      matrices += n.has_matrix && n.matrix != glm::transpose(n.matrix);
      turned_scaled += !n.has_matrix && n.rotation.w < 0.999 && n.scale != glm::dvec3(n.scale.x);
      under_parent += n.mesh && n.parent;
    }
    CHECK(matrices >= 1);
    CHECK(turned_scaled >= 1);
    CHECK(under_parent >= 1);
    REQUIRE(l.doc.cameras.size() == 1);
    CHECK(l.scene.canvas.width != l.scene.canvas.height);
    // Everything in these files is drawn; the one note may be that some primitives are single-sided
    // (their front faces face the camera, so an engine that culls draws the same).
    for (const std::string& note : l.scene.notes) CHECK(note.find("single-sided primitive") != std::string::npos);

    // The composer written here, without a bug, is the reader's chain.
    const Scene mine = Composed(l, Bug::kNone);
    for (std::size_t i = 0; i < mine.instances.size(); ++i) {
      const glm::dmat4 a = ModelMatrix(mine.instances[i].transform), b = ModelMatrix(l.scene.instances[i].transform);
      for (int c = 0; c < 4; ++c) {
        for (int r = 0; r < 4; ++r) CHECK(std::abs(a[c][r] - b[c][r]) < 1e-12);
      }
    }
  }
}

TEST_CASE("glTF coverage: the twin's image of each shipped glTF scene passes under any shading and clear colour",
          "[verify][coverage][gltf]") {
  std::filesystem::remove(std::filesystem::path(TWINRASTER_BINARY_DIR) / "verify-gltf-coverage.md");
  AppendTable("verify-gltf-coverage.md", "| scene | canvas | certainly covered | certainly uncovered | uncertain |");
  AppendTable("verify-gltf-coverage.md", "|---|---|---|---|---|");
  const Rgb8 magenta{255, 0, 255};
  std::size_t judged = 0;
  for (const std::string& file : kScenes) {
    const Loaded l = Load(file);
    const DrawList list = BuildDrawList(l.scene);
    const Image twin = cpu::RenderOnCpu(list);
    const Rgb8 from = l.scene.canvas.background;
    verify::CoverageVerification first;
    for (const Shade shade : {Shade::kConstant, Shade::kGradient, Shade::kNoise}) {
      for (const bool own_clear : {false, true}) {
        verify::CoverageOptions options;
        if (own_clear) options.background = magenta;
        const run::CoverageJudgement j =
            run::JudgeCoverage(l.scene, list, Recolour(twin, from, own_clear ? magenta : from, shade), options);
        INFO(file << ", shading " << int(shade) << (own_clear ? ", clear colour (255, 0, 255)" : ""));
        CHECK(j.coverage.Violations() == 0);
        CHECK(j.verdict == run::Verdict::kVerified);
        if (!judged++ || (shade == Shade::kConstant && !own_clear)) first = j.coverage;
      }
    }
    // Something is there to judge: a broken image could fail.
    CHECK(first.certainly_covered > 1000);
    CHECK(first.certainly_uncovered > 1000);
    std::ostringstream row;
    row << "| " << file << " | " << twin.width << "x" << twin.height << " | " << first.certainly_covered << " | "
        << first.certainly_uncovered << " | " << first.uncertain << " |";
    AppendTable("verify-gltf-coverage.md", row.str());
  }
  CHECK(judged == kScenes.size() * 3 * 2);
}

TEST_CASE("glTF coverage: each glTF import bug fails on every shipped glTF scene, under shading noise",
          "[verify][coverage][gltf]") {
  std::filesystem::remove(std::filesystem::path(TWINRASTER_BINARY_DIR) / "verify-gltf-coverage-bugs.md");
  AppendTable("verify-gltf-coverage-bugs.md",
              "| defect | scene | px whose coverage differs | of them certain | spills | holes | verdict |");
  AppendTable("verify-gltf-coverage-bugs.md", "|---|---|---|---|---|---|---|");
  std::map<std::string, std::size_t> failed;
  std::size_t judged = 0;
  std::uint32_t seed = 11;
  for (const std::string& file : kScenes) {
    const Loaded l = Load(file);
    const DrawList list = BuildDrawList(l.scene);
    const Image twin = cpu::RenderOnCpu(list);
    const Rgb8 bg = l.scene.canvas.background;
    verify::VerifyOptions loosest;
    loosest.reach = true;
    const std::vector<verify::Reach> reach = verify::VerifyImage(l.scene, list, twin, loosest).reach;
    for (const Variant& v : Variants()) {
      const Scene bug = v.make(l);
      REQUIRE(bug.canvas.width == twin.width);
      REQUIRE(bug.canvas.height == twin.height);
      const Image image = Recolour(Twin(bug), bg, bg, Shade::kNoise, ++seed);
      std::uint64_t differing = 0, certain = 0;
      for (std::uint32_t y = 0; y < twin.height; ++y) {
        for (std::uint32_t x = 0; x < twin.width; ++x) {
          const bool d = Is(twin.pixel(x, y), bg) != Is(image.pixel(x, y), bg);
          differing += d;
          certain += d && reach[std::size_t{y} * twin.width + x] != verify::Reach::kMaybe;
        }
      }
      const run::CoverageJudgement j = run::JudgeCoverage(l.scene, list, image);
      INFO(file << ": " << v.name << ": " << differing << " px differ in coverage, " << certain
                << " where it is certain; " << j.coverage.spills << " spills, " << j.coverage.holes << " holes");
      // Failed, never passed or inconclusive; each certain pixel the bug moves is a violation.
      CHECK(j.verdict == run::Verdict::kDiffering);
      CHECK(j.coverage.Violations() > 0);
      CHECK(j.coverage.Violations() == certain);
      failed[v.name] += j.verdict == run::Verdict::kDiffering;
      std::ostringstream row;
      row << "| " << v.name << " | " << file << " | " << differing << " | " << certain << " | " << j.coverage.spills
          << " | " << j.coverage.holes << " | " << run::VerdictName(j.verdict) << " |";
      AppendTable("verify-gltf-coverage-bugs.md", row.str());
      ++judged;
    }
  }
  CHECK(judged == kScenes.size() * Variants().size());
  CHECK(Variants().size() == 7);
  for (const Variant& v : Variants()) {
    INFO(v.name);
    CHECK(failed[v.name] == kScenes.size());
  }
}
