// verify --coverage's judgement (run::JudgeCoverage): the twin's images of shipped scenes, recoloured
// as an engine's own shading would, pass; the twin's images of scenes with a transform bug,
// recoloured with noise so that only coverage can tell, fail. Also: the reach is the same with
// and without the verifier's fast paths, and the judgement's counts follow its rules.
#include "chain/draw_list.hpp"
#include "chain/matrices.hpp"
#include "cpu/cpu_renderer.hpp"
#include "engine_shading.hpp"
#include "run/judge_coverage.hpp"
#include "scene/obj_scene.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"
#include "verify/verifier.hpp"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <random>
#include <sstream>
#include <string>
#include <vector>

using namespace twinraster;
using test::Is;
using test::kShades;
using test::Recolour;
using test::Shade;

namespace {

// Scenes with several instances, rotations, scales, list transforms, a lookat camera, non-square
// canvases and an OBJ mesh: what a transform bug can go wrong on.
const std::vector<std::string> kScenes = {
    "scenes/cgfs-instances.json",  "scenes/catlike-rotations.json", "scenes/lookat.json",
    "scenes/cgfs-transforms.json", "scenes/cgfs-figure-10-4.json",  "scenes/lit-mixed.json",
    "scenes/meshes/knot.obj",
};

Scene Load(const std::string& file) { return LoadSceneOrObj(test::SourcePath(file)); }
Image Twin(const Scene& scene) { return cpu::RenderOnCpu(BuildDrawList(scene)); }

Image ShiftedRight(const Image& image, Rgb8 background) {
  Image out = image;
  for (std::uint32_t y = 0; y < image.height; ++y) {
    for (std::uint32_t x = 0; x < image.width; ++x) {
      const std::uint8_t* src = x ? image.pixel(x - 1, y) : nullptr;
      std::uint8_t* p = out.pixel(x, y);
      if (src)
        std::copy_n(src, 4, p);
      else
        p[0] = background.r, p[1] = background.g, p[2] = background.b;
    }
  }
  return out;
}

// --- The transform bugs, made on the Scene: each gives the mutated scene, or nothing when it
// leaves every instance's F and the camera as they were (it cannot change the picture).

bool IsIdentity(const TransformStep& s) {
  switch (s.kind) {
    case TransformStep::Kind::kScale: return s.vector == glm::dvec3(1, 1, 1);
    case TransformStep::Kind::kTranslation: return s.vector == glm::dvec3(0, 0, 0);
    case TransformStep::Kind::kRotation: return s.rotation == glm::dmat3(1.0);
    case TransformStep::Kind::kMatrix: return s.matrix == glm::dmat4(1.0);
  }
  return false;
}

// The instance's whole transform as a list of steps, in the order applied, identities left out.
std::vector<TransformStep> AsSteps(const Transform& t) {
  std::vector<TransformStep> steps = t.steps ? *t.steps : std::vector<TransformStep>{};
  TransformStep s;
  s.kind = TransformStep::Kind::kScale, s.vector = t.scale;
  steps.push_back(s);
  s = {};
  s.kind = TransformStep::Kind::kRotation, s.rotation = t.rotation;
  steps.push_back(s);
  s = {};
  s.kind = TransformStep::Kind::kTranslation, s.vector = t.translation;
  steps.push_back(s);
  std::erase_if(steps, IsIdentity);
  return steps;
}

Transform FromSteps(std::vector<TransformStep> steps) {
  Transform t;
  t.steps = std::make_shared<const std::vector<TransformStep>>(std::move(steps));
  return t;
}

using Mutation = std::function<void(Scene&)>;

std::optional<Scene> Mutated(const Scene& scene, const Mutation& mutate) {
  Scene m = scene;
  mutate(m);
  const DrawList a = BuildDrawList(scene), b = BuildDrawList(m);
  bool changed = a.draws.size() != b.draws.size();
  for (std::size_t d = 0; !changed && d < a.draws.size(); ++d) changed = a.draws[d].F != b.draws[d].F;
  if (!changed) return std::nullopt;
  return m;
}

void EachInstance(Scene& s, const std::function<void(std::vector<TransformStep>&)>& f) {
  for (Instance& i : s.instances) {
    std::vector<TransformStep> steps = AsSteps(i.transform);
    f(steps);
    i.transform = FromSteps(std::move(steps));
  }
}

TransformStep Mirror(glm::dvec3 axes) {
  TransformStep s;
  s.kind = TransformStep::Kind::kScale, s.vector = axes;
  return s;
}

const std::vector<std::pair<std::string, Mutation>>& Defects() {
  static const std::vector<std::pair<std::string, Mutation>> defects = {
      {"translation-rotation-scale in the wrong order",
       [](Scene& s) { EachInstance(s, [](auto& steps) { std::reverse(steps.begin(), steps.end()); }); }},
      {"rotations transposed (read row-major)",
       [](Scene& s) {
         EachInstance(s, [](auto& steps) {
           for (TransformStep& step : steps) step.rotation = glm::transpose(step.rotation);
         });
         s.camera.rotation = glm::transpose(s.camera.rotation);
       }},
      {"handedness mirrored: world x negated",
       [](Scene& s) { EachInstance(s, [](auto& steps) {
                        steps.push_back(Mirror({-1, 1, 1}));
                      }); }},
      {"handedness mirrored: world z negated",
       [](Scene& s) { EachInstance(s, [](auto& steps) {
                        steps.push_back(Mirror({1, 1, -1}));
                      }); }},
      {"field of view off by 1 % (viewport x 1.01)",
       [](Scene& s) { s.viewport.width *= 1.01, s.viewport.height *= 1.01; }},
      {"aspect ratio ignored (square viewport, non-square canvas)",
       [](Scene& s) {
         if (s.canvas.width != s.canvas.height) s.viewport.height = s.viewport.width;
       }},
      {"child not composed with its parent (its last step missing)",
       [](Scene& s) {
         EachInstance(s, [](auto& steps) {
           if (steps.size() >= 2) steps.pop_back();
         });
       }},
  };
  return defects;
}

// Each test case writes its own file: CTest runs them in parallel, and one file shared by two
// of them came out with their rows interleaved.
void AppendTable(const std::string& file, const std::string& line) {
  std::ofstream out(std::filesystem::path(TWINRASTER_BINARY_DIR) / file, std::ios::app);
  out << line << "\n";
}

}  // namespace

TEST_CASE("coverage: the reach is the same with and without the verifier's fast paths", "[verify][coverage]") {
  std::size_t judged = 0;
  for (const std::string& file : kScenes) {
    for (const bool wireframe : {false, true}) {
      Scene scene = Load(file);
      scene.wireframe = wireframe;
      const DrawList list = BuildDrawList(scene);
      const Image image = cpu::RenderOnCpu(list);
      verify::VerifyOptions fast;
      fast.reach = true;
      verify::VerifyOptions slow = fast;
      slow.fast_paths = false;
      const verify::Verification a = verify::VerifyImage(scene, list, image, fast);
      const verify::Verification b = verify::VerifyImage(scene, list, image, slow);
      INFO(file << (wireframe ? " (wireframe)" : ""));
      REQUIRE(a.reach.size() == std::size_t{image.width} * image.height);
      CHECK(a.reach == b.reach);
      CHECK(std::count(a.reach.begin(), a.reach.end(), verify::Reach::kCertain) > 0);
      CHECK(std::count(a.reach.begin(), a.reach.end(), verify::Reach::kNone) > 0);
      ++judged;
    }
  }
  CHECK(judged == 2 * kScenes.size());
}

TEST_CASE("coverage: the twin's image under any shading and clear colour passes, and one pixel off fails",
          "[verify][coverage]") {
  std::filesystem::remove(std::filesystem::path(TWINRASTER_BINARY_DIR) / "verify-coverage.md");
  AppendTable(
      "verify-coverage.md",
      "| scene | covered, certain | uncovered, certain | uncertain | of them covered by the twin | violations, 5 "
      "shadings "
      "x 2 clear colours | violations shifted 1 px right |");
  AppendTable("verify-coverage.md", "|---|---|---|---|---|---|---|");
  std::size_t judged = 0;
  const Rgb8 magenta{255, 0, 255};
  for (const std::string& file : kScenes) {
    const Scene scene = Load(file);
    const DrawList list = BuildDrawList(scene);
    const Image twin = cpu::RenderOnCpu(list);
    const Rgb8 from = scene.canvas.background;
    std::uint64_t violations = 0;
    verify::CoverageVerification first;
    for (const auto& [shade, name] : kShades) {
      for (const bool own_clear : {false, true}) {
        const Rgb8 clear = own_clear ? magenta : from;
        verify::CoverageOptions options;
        if (own_clear) options.background = clear;
        const run::CoverageJudgement j = run::JudgeCoverage(scene, list, Recolour(twin, from, clear, shade), options);
        INFO(file << ", " << name << (own_clear ? ", clear colour (255, 0, 255) given" : ", the scene's clear colour"));
        CHECK(j.coverage.Violations() == 0);
        CHECK(j.verdict == run::Verdict::kVerified);
        CHECK(j.coverage.certainly_covered + j.coverage.certainly_uncovered + j.coverage.uncertain ==
              std::uint64_t{twin.width} * twin.height);
        violations += j.coverage.Violations();
        if (shade == Shade::kConstant && !own_clear) first = j.coverage;
        ++judged;
      }
    }
    // The same image judged without the clear colour it was drawn with: all its background spills.
    const Image magenta_clear = Recolour(twin, from, magenta, Shade::kNoise);
    const run::CoverageJudgement wrong_clear = run::JudgeCoverage(scene, list, magenta_clear);
    CHECK(wrong_clear.verdict == run::Verdict::kDiffering);
    CHECK(wrong_clear.coverage.spills == wrong_clear.coverage.certainly_uncovered);
    // The margin: one pixel right is caught.
    const run::CoverageJudgement shifted = run::JudgeCoverage(scene, list, ShiftedRight(twin, from));
    CHECK(shifted.verdict == run::Verdict::kDiffering);
    std::ostringstream row;
    row << "| " << file << " | " << first.certainly_covered << " | " << first.certainly_uncovered << " | "
        << first.uncertain << " | " << first.uncertain_covered << " | " << violations << " | "
        << shifted.coverage.Violations() << " |";
    AppendTable("verify-coverage.md", row.str());
  }
  CHECK(judged == kScenes.size() * kShades.size() * 2);
}

TEST_CASE("coverage: every transform bug is caught on every shipped scene it changes, under shading noise",
          "[verify][coverage]") {
  std::filesystem::remove(std::filesystem::path(TWINRASTER_BINARY_DIR) / "verify-coverage-bugs.md");
  AppendTable(
      "verify-coverage-bugs.md",
      "| defect | scene | px whose coverage differs from the twin's | of them where coverage is certain | spills | "
      "holes | verdict |");
  AppendTable("verify-coverage-bugs.md", "|---|---|---|---|---|---|---|");
  std::map<std::string, std::size_t> caught, unchanged;
  std::size_t judged = 0;
  for (const std::string& file : kScenes) {
    const Scene scene = Load(file);
    const DrawList list = BuildDrawList(scene);
    const Image twin = cpu::RenderOnCpu(list);
    const Rgb8 bg = scene.canvas.background;
    verify::VerifyOptions loosest;
    loosest.reach = true;
    const std::vector<verify::Reach> reach = verify::VerifyImage(scene, list, twin, loosest).reach;
    std::uint32_t seed = 7;
    for (const auto& [name, mutate] : Defects()) {
      const std::optional<Scene> bug = Mutated(scene, mutate);
      if (!bug) continue;  // the bug leaves this scene's chain as it was
      const Image image = Recolour(Twin(*bug), bg, bg, Shade::kNoise, ++seed);
      // What the bug changes: pixels covered in one image and not the other, and of them those
      // where the verifier is certain of the coverage (elsewhere a correct engine may differ too).
      std::uint64_t differing = 0, certain = 0;
      for (std::uint32_t y = 0; y < twin.height; ++y) {
        for (std::uint32_t x = 0; x < twin.width; ++x) {
          const bool d = Is(twin.pixel(x, y), bg) != Is(image.pixel(x, y), bg);
          differing += d;
          certain += d && reach[std::size_t{y} * twin.width + x] != verify::Reach::kMaybe;
        }
      }
      const run::CoverageJudgement j = run::JudgeCoverage(scene, list, image);
      INFO(file << ": " << name << ": " << differing << " px differ in coverage, " << certain
                << " where it is certain; " << j.coverage.spills << " spills, " << j.coverage.holes << " holes");
      // Each certain pixel the bug changes is a violation, and nothing else is.
      CHECK(j.coverage.Violations() == certain);
      if (certain > 0) {
        CHECK(j.verdict == run::Verdict::kDiffering);
        ++caught[name];
      } else {
        CHECK(j.verdict != run::Verdict::kDiffering);
        ++unchanged[name];  // a bug whose picture is the twin's, coverage-wise (a symmetric scene mirrored)
      }
      std::ostringstream row;
      row << "| " << name << " | " << file << " | " << differing << " | " << certain << " | " << j.coverage.spills
          << " | " << j.coverage.holes << " | " << run::VerdictName(j.verdict) << " |";
      AppendTable("verify-coverage-bugs.md", row.str());
      ++judged;
    }
  }
  // Every bug caught on at least two scenes, none of the loops empty, and the few a bug leaves
  // unchanged are counted, not passed over.
  std::size_t all = 0;
  for (const auto& [name, mutate] : Defects()) {
    INFO(name);
    CHECK(caught[name] >= 2);
    all += caught[name] + unchanged[name];
  }
  CHECK(all == judged);
  CHECK(judged >= 5 * Defects().size());
  std::size_t none = 0;
  for (const auto& [name, n] : unchanged) none += n;
  CHECK(none * 10 < judged);  // at most a tenth of the variants leave the coverage as it was
}

TEST_CASE("coverage: shading that gives the clear colour fails unless a stated tolerance allows it",
          "[verify][coverage]") {
  const Scene scene = Load("scenes/cgfs-instances.json");
  const DrawList list = BuildDrawList(scene);
  const Image twin = cpu::RenderOnCpu(list);
  const Rgb8 bg = scene.canvas.background;
  // One covered pixel in 200 shaded exactly the clear colour (a highlight saturating to white).
  Image image = Recolour(twin, bg, bg, Shade::kNoise);
  const verify::CoverageVerification reference = run::JudgeCoverage(scene, list, image).coverage;
  REQUIRE(reference.Violations() == 0);
  std::size_t painted = 0;
  for (std::size_t i = 0; i < reference.pixels.size(); i += 200) {
    const std::uint32_t x = std::uint32_t(i % twin.width), y = std::uint32_t(i / twin.width);
    if (Is(twin.pixel(x, y), bg)) continue;
    std::uint8_t* p = image.pixel(x, y);
    p[0] = bg.r, p[1] = bg.g, p[2] = bg.b;
    ++painted;
  }
  REQUIRE(painted > 10);
  const run::CoverageJudgement strict = run::JudgeCoverage(scene, list, image, {}, true);
  CHECK(strict.verdict == run::Verdict::kDiffering);
  CHECK(strict.coverage.spills == 0);
  CHECK(strict.coverage.holes > 0);
  CHECK(strict.coverage.holes <= painted);  // uncertain edge pixels among them are free
  REQUIRE(strict.map);
  CHECK(std::count(strict.coverage.pixels.begin(), strict.coverage.pixels.end(), verify::CoveragePixel::kHole) ==
        std::ptrdiff_t(strict.coverage.holes));
  CHECK(Is(strict.map->pixel(strict.coverage.first_hole->x, strict.coverage.first_hole->y), Rgb8{0, 64, 255}));

  verify::CoverageOptions tolerant;
  tolerant.hole_tolerance_percent = 1;  // 1 % of the certainly covered pixels, more than 1 in 200
  const run::CoverageJudgement within = run::JudgeCoverage(scene, list, image, tolerant, true);
  CHECK(within.verdict == run::Verdict::kVerified);
  CHECK(within.coverage.holes == strict.coverage.holes);
  CHECK(within.coverage.holes_allowed == within.coverage.certainly_covered / 100);
  CHECK(Is(within.map->pixel(within.coverage.first_hole->x, within.coverage.first_hole->y), Rgb8{0, 200, 255}));
  tolerant.hole_tolerance_percent = 0.1;  // fewer than painted
  CHECK(run::JudgeCoverage(scene, list, image, tolerant).verdict == run::Verdict::kDiffering);
}

TEST_CASE("coverage: an empty or a full image of a scene that covers nothing certainly is inconclusive, not passed",
          "[verify][coverage]") {
  Scene scene = Load("scenes/cgfs-instances.json");
  scene.camera.position = {0, 0, 100};  // everything behind the camera
  const DrawList list = BuildDrawList(scene);
  const Image empty = cpu::RenderOnCpu(list);
  const run::CoverageJudgement j = run::JudgeCoverage(scene, list, empty);
  CHECK(j.coverage.certainly_covered == 0);
  CHECK(j.verdict == run::Verdict::kInconclusive);

  // Camera inside a cube: every pixel is certainly covered, so an image covered everywhere passes
  // whatever the transform: inconclusive.
  const Scene inside = Load("scenes/hard/camera-inside-cube.json");
  const DrawList inside_list = BuildDrawList(inside);
  const run::CoverageJudgement k = run::JudgeCoverage(inside, inside_list, cpu::RenderOnCpu(inside_list));
  CHECK(k.coverage.certainly_uncovered == 0);
  CHECK(k.verdict == run::Verdict::kInconclusive);
}

TEST_CASE("coverage: bad inputs are refused with a reason", "[verify][coverage]") {
  const Scene scene = Load("scenes/cgfs-instances.json");
  const Image small(10, 10);
  CHECK_THROWS_AS(run::JudgeCoverage(scene, small), std::invalid_argument);
  verify::CoverageOptions options;
  options.hole_tolerance_percent = 101;
  CHECK_THROWS_AS(run::JudgeCoverage(scene, Twin(scene), options), std::invalid_argument);
  verify::Verification no_reach = verify::VerifyImage(scene, BuildDrawList(scene), Twin(scene));
  CHECK_THROWS_AS(verify::JudgeCoverage(no_reach, Twin(scene), scene.canvas.background, {}), std::invalid_argument);
}
