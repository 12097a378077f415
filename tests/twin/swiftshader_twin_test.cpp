// The twin with SwiftShader's rules against the installed SwiftShader (Debian's chromium package):
// the rules are chosen from what the device reports; every shipped scene and mesh, filled and in
// wireframe, the million cubes, random, lit, vertex-coloured and adversarial scenes (subpixel ties,
// slivers, corners behind the eye, NaN w, denormal depths) give 0 differing pixels; and denormals as zero and the
// rasterizer as a whole are each shown to change pixels, so leaving them out would show.
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "cpu/platform.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "random_scene.hpp"
#include "run/backend_draws.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/lit_scene.hpp"
#include "support/test_support.hpp"
#include "twin_rules/twin_rules.hpp"
#include "twin_support.hpp"

#include <glm/vec3.hpp>

#include <filesystem>
#include <memory>
#include <random>
#include <stdexcept>
#include <vector>

using namespace twinraster;

namespace {

gpu::GpuRenderer& SwiftShader() { return test::SharedSwiftShader(); }

twin_rules::TwinRules SwiftShaderRules() {
  return twin_rules::ChooseTwinRules(run::FactsOf(SwiftShader().Device()), twin_rules::DetectCpuPath());
}

cpu::CpuOptions Twin(cpu::CpuOptions options = {}) {
  const twin_rules::TwinRules twin = SwiftShaderRules();
  if (!twin.exact) throw std::runtime_error("no SwiftShader rules here: " + twin.text);
  options.rules = twin.rules;
  return options;
}

struct Pair {
  Image gpu, cpu;
  Comparison comparison;
};

// SwiftShader's image and the twin's; the twin's again in chunks of 24 triangles on 2 threads
// (depth tiles refreshed between chunks) must not change.
Pair RenderPair(const DrawList& list) {
  Pair p{SwiftShader().Render(list), cpu::RenderOnCpu(list, Twin()), {}};
  if (cpu::RenderOnCpu(list, Twin(cpu::CpuOptions{.threads = 2, .chunk_triangles = 24})).rgba != p.cpu.rgba) {
    throw std::runtime_error("the twin's SwiftShader image changed when drawn in chunks of 24 triangles");
  }
  p.comparison = CompareImages(p.gpu, p.cpu);
  return p;
}

std::string Differences(const Pair& p) {
  return std::to_string(p.comparison.differing_pixels) + " differing pixels, max channel difference " +
         std::to_string(p.comparison.max_channel_difference);
}

void RequireNoValidationMessages() {
  std::string text;
  for (const std::string& m : SwiftShader().ValidationMessages()) text += m + "\n";
  INFO(text);
  REQUIRE(text.empty());
}

Scene Shipped(const std::filesystem::path& file, bool wireframe) {
  Scene scene = LoadSceneOrObj(file);
  scene.wireframe = scene.wireframe || wireframe;
  return scene;
}

// A list of random triangles on a 256 x 256 canvas: flat (w = 1), with corners placed in window
// pixels on pixel centres, corners, both devices' subpixel grids and SwiftShader's ties; or with
// perspective (w = z), with corners near, at and behind the eye plane. Every fifth a sliver, every
// eleventh of zero area.
DrawList Adversarial(std::uint32_t seed, bool perspective, bool wireframe) {
  std::mt19937 rng(seed);
  std::uniform_int_distribution<int> pixel(-30, 285), kind(0, 6), sub(0, 15);
  std::uniform_real_distribution<double> anywhere(-40.0, 296.0), depth(-0.2, 1.2), unit(-1.0, 1.0);
  const auto window = [&] {
    const int k = pixel(rng);
    switch (kind(rng)) {
      case 0: return k + 0.5;                                // a pixel centre
      case 1: return k + 0.0;                                // a pixel corner
      case 2: return k + 0.5 + (sub(rng) + 0.5) / 16.0;      // a tie for 4-bit snapping
      case 3: return k + 0.5 + sub(rng) / 16.0;              // on the 4-bit grid
      case 4: return k + 0.5 + (sub(rng) * 16 + 8) / 256.0;  // on lavapipe's grid, between SwiftShader's
      default: return anywhere(rng);
    }
  };
  DrawList list;
  list.width = list.height = 256;
  list.background = {255, 255, 255};
  list.wireframe = wireframe;
  DrawMesh mesh;
  for (int t = 0; t < 600; ++t) {
    std::array<glm::vec3, 3> tri;
    for (glm::vec3& p : tri) {
      if (perspective) {
        const double w = t % 3 == 0 ? unit(rng) * 0.05 : unit(rng) * 2.0;  // near, at and behind the eye
        p = {static_cast<float>(unit(rng) * 1.5 * w), static_cast<float>(unit(rng) * 1.5 * w), static_cast<float>(w)};
      } else {
        p = {static_cast<float>((window() - 128.0) / 128.0), static_cast<float>((window() - 128.0) / 128.0),
             static_cast<float>(depth(rng))};
      }
    }
    if (t % 5 == 0) tri[2] = tri[1] + (tri[1] - tri[0]) * 1e-3f;  // a sliver, nearly a line
    if (t % 11 == 0) tri[2] = tri[1];                             // a line, zero area
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec3& p : tri) mesh.positions.push_back(p);
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.colours.push_back({static_cast<std::uint8_t>(t * 37), static_cast<std::uint8_t>(255 - t * 11), 90});
  }
  list.meshes.push_back(mesh);
  // Column-major (f[column][row]): x' = x, y' = y; flat: z' = z/2 + 1/4, w' = 1; with perspective:
  // z' = x/10 + z/2, w' = z.
  glm::mat4 f(1.0f);
  f[2][2] = 0.5f;
  if (perspective) {
    f[0][2] = 0.1f, f[2][3] = 1.0f, f[3][3] = 0.0f;
  } else {
    f[3][2] = 0.25f;
  }
  list.draws.push_back(DrawCall{0, f});
  return list;
}

// Triangles with a corner whose clip w is NaN while x, y and z are finite (w = 1e37 (x + y) + 1
// overflows to inf - inf): SwiftShader's FINITE bit does not look at w, so clipping meets the NaN.
// `variant` moves which corners carry it; filled, or in wireframe.
DrawList NanW(int variant, bool wireframe) {
  DrawList list;
  list.width = list.height = 64;
  list.background = {255, 255, 255};
  list.wireframe = wireframe;
  DrawMesh mesh;
  constexpr float kBig = 30.0f;
  mesh.positions = {{0.2f, 0.1f, 0.5f}, {kBig, -kBig, 0.5f}, {-0.3f, 0.4f, 0.5f}, {0.5f, -0.5f, 0.5f}};
  if (variant == 1) mesh.positions[1] = {-kBig, kBig, 0.5f};
  if (variant == 2) mesh.positions[2] = {kBig, -kBig, 0.3f};
  mesh.triangles = {{0, 1, 2}, {0, 2, 3}, {1, 3, 0}};
  mesh.colours = {{200, 0, 0}, {0, 200, 0}, {0, 0, 200}};
  list.meshes.push_back(mesh);
  glm::mat4 f(1.0f);
  f[0][3] = 1e37f, f[1][3] = 1e37f;  // w = 1e37 x + 1e37 y + 1
  list.draws.push_back(DrawCall{0, f});
  return list;
}

// Two overlapping squares at w = 1: the first at depth 1e-39 (a denormal, 0 where denormals are
// zero), the second, drawn later, at depth 0. With LESS the second passes only if the first stored
// a denormal rather than 0.
DrawList DenormalDepths() {
  DrawList list;
  list.width = list.height = 64;
  list.background = {255, 255, 255};
  DrawMesh mesh;
  const auto square = [&mesh](float z, Rgb8 colour) {
    const auto base = static_cast<std::uint32_t>(mesh.positions.size());
    for (const glm::vec2 c :
         {glm::vec2(-0.5f, -0.5f), glm::vec2(0.5f, -0.5f), glm::vec2(0.5f, 0.5f), glm::vec2(-0.5f, 0.5f)})
      mesh.positions.push_back({c.x, c.y, z});
    mesh.triangles.push_back({base, base + 1, base + 2});
    mesh.triangles.push_back({base, base + 2, base + 3});
    mesh.colours.push_back(colour);
    mesh.colours.push_back(colour);
  };
  square(1e-39f, {200, 0, 0});
  square(0.0f, {0, 0, 200});
  list.meshes.push_back(mesh);
  list.draws.push_back(DrawCall{0, glm::mat4(1.0f)});
  return list;
}

}  // namespace

TEST_CASE("SwiftShader: the twin's rules are chosen from what the device reports", "[twin][swiftshader]") {
  const gpu::DeviceIdentity& d = SwiftShader().Device();
  const twin_rules::TwinRules twin = SwiftShaderRules();
  INFO(d.name << ": " << twin.text);
  REQUIRE(twin.exact);
  CHECK(twin.rules.rasterizer == cpu::Rasterizer::kSwiftShader);
  CHECK(twin.rules.flush_denormals);
  CHECK_FALSE(twin.rules.fused_multiply_add);
  CHECK(cpu::TwinDeviceLimits(twin.rules).subpixel_bits == int(d.subpixel_bits));
  // What would make it another SwiftShader: each is named, none gets rules.
  const twin_rules::DeviceFacts facts = run::FactsOf(d);
  twin_rules::DeviceFacts llvm = facts, upstream = facts, newer = facts;
  llvm.name = "SwiftShader Device (LLVM 10.0.0)";
  upstream.subpixel_bits = 8;
  newer.driver_version = (5u << 22) | 1;
  for (const twin_rules::DeviceFacts& other : {llvm, upstream, newer}) {
    const twin_rules::TwinRules rules = twin_rules::ChooseTwinRules(other, twin_rules::DetectCpuPath());
    INFO(rules.text);
    CHECK_FALSE(rules.exact);
    CHECK(rules.text.starts_with("no bit-exact rules for " + other.name));
  }
  twin_rules::CpuPath without_sse41 = twin_rules::DetectCpuPath();
  without_sse41.cpuid_sse4_1 = false;
  CHECK_FALSE(twin_rules::ChooseTwinRules(facts, without_sse41).exact);
}

TEST_CASE("SwiftShader: every shipped scene and mesh, filled and in wireframe: GPU image == twin image",
          "[twin][swiftshader]") {
  std::vector<std::filesystem::path> files = test::ShippedScenes();
  for (const auto& mesh : std::filesystem::directory_iterator(test::SourcePath("scenes/meshes"))) {
    if (mesh.path().extension() == ".obj") files.push_back(mesh.path());
  }
  int judged = 0;
  for (const auto& file : files) {
    for (const bool wireframe : {false, true}) {
      INFO(file.string() << (wireframe ? " --wireframe" : ""));
      const Scene scene = Shipped(file, wireframe);
      const Pair p = RenderPair(BuildDrawList(scene));
      INFO(Differences(p));
      CHECK(p.comparison.Equal());
      CHECK(test::CountNotColour(p.cpu, scene.canvas.background) > 100);
      ++judged;
    }
  }
  CHECK(judged == 2 * (46 + 5));  // the 46 scenes test::ShippedScenes() checks for, and 5 meshes
  RequireNoValidationMessages();
}

TEST_CASE("SwiftShader: the million-instance scenes at 480x270, filled and in wireframe",
          "[twin][swiftshader][large]") {
  for (const auto& file : test::LargeShippedScenes()) {
    Scene scene = LoadScene(file);
    scene.canvas.width = 480;
    scene.canvas.height = 270;
    for (const bool wireframe : {false, true}) {
      INFO(file.string() << (wireframe ? " --wireframe" : ""));
      scene.wireframe = wireframe;
      const DrawList list = BuildDrawList(scene);
      const Comparison c = CompareImages(SwiftShader().Render(list), cpu::RenderOnCpu(list, Twin()));
      INFO(c.differing_pixels << " differing pixels");
      CHECK(c.Equal());
    }
  }
  RequireNoValidationMessages();
}

TEST_CASE("SwiftShader: random scenes, filled, in wireframe and lit: GPU image == twin image",
          "[twin][swiftshader][random]") {
  constexpr std::uint32_t kScenes = 1000;
  int drawn = 0, judged = 0;
  for (std::uint32_t seed = 1; seed <= kScenes; ++seed) {
    for (int kind = 0; kind < 3; ++kind) {
      Scene scene;
      if (kind == 2) {
        scene = test::RandomLitScene(seed);
      } else {
        nlohmann::ordered_json json = test::RandomSceneJson(seed);
        if (kind == 1) json["wireframe"] = true;
        scene = ParseScene(json.dump(1), "random-" + std::to_string(seed) + ".json");
      }
      const Pair p = RenderPair(BuildDrawList(scene));
      INFO("seed " << seed << " kind " << kind << ": " << Differences(p));
      CHECK(p.comparison.Equal());
      drawn += test::CountNotColour(p.cpu, scene.canvas.background) > 0 ? 1 : 0;
      ++judged;
    }
  }
  CHECK(judged == int(3 * kScenes));
  CHECK(drawn >= judged * 7 / 10);  // the generators' scenes really draw
  RequireNoValidationMessages();
}

TEST_CASE("SwiftShader: random vertex-coloured scenes, unlit, flat and Gouraud: GPU image == twin image",
          "[twin][swiftshader][vertex-colours][random]") {
  constexpr std::uint32_t kScenes = 1000;
  int drawn = 0, judged = 0, unlit = 0;
  for (std::uint32_t seed = 1; seed <= kScenes; ++seed) {
    const Scene scene = test::RandomVertexColourScene(seed);
    unlit += scene.lighting ? 0 : 1;
    const Pair p = RenderPair(BuildDrawList(scene));
    INFO("seed " << seed << ": " << Differences(p));
    CHECK(p.comparison.Equal());
    drawn += test::CountNotColour(p.cpu, scene.canvas.background) > 0 ? 1 : 0;
    ++judged;
  }
  CHECK(judged == int(kScenes));
  CHECK(unlit == int(kScenes / 3));  // seeds divisible by 3
  CHECK(drawn >= judged * 7 / 10);
  RequireNoValidationMessages();
}

TEST_CASE("SwiftShader: adversarial triangles, ties on both grids, slivers, corners at and behind the eye",
          "[twin][swiftshader][random]") {
  // Pixels drawn per configuration: each must draw, so that none passes by drawing nothing.
  std::uint64_t covered[2][2] = {{0, 0}, {0, 0}};
  for (std::uint32_t seed = 1; seed <= 40; ++seed) {
    for (const bool perspective : {false, true}) {
      for (const bool wireframe : {false, true}) {
        const DrawList list = Adversarial(seed, perspective, wireframe);
        const Pair p = RenderPair(list);
        INFO("seed " << seed << (perspective ? " perspective" : " flat") << (wireframe ? " wireframe" : " filled")
                     << ": " << Differences(p));
        CHECK(p.comparison.Equal());
        covered[perspective][wireframe] += test::CountNotColour(p.cpu, list.background);
      }
    }
  }
  for (const bool perspective : {false, true}) {
    for (const bool wireframe : {false, true}) {
      INFO((perspective ? "perspective" : "flat") << (wireframe ? " wireframe" : " filled"));
      CHECK(covered[perspective][wireframe] > 40 * 20000);
    }
  }
  // A NaN w: filled, SwiftShader draws none of these triangles; in wireframe, the edges between
  // finite corners. The twin must agree either way.
  std::uint64_t nan_wireframe = 0;
  for (int variant = 0; variant < 3; ++variant) {
    for (const bool wireframe : {false, true}) {
      const DrawList list = NanW(variant, wireframe);
      const Pair p = RenderPair(list);
      INFO("NaN w, variant " << variant << (wireframe ? " wireframe" : " filled") << ": " << Differences(p));
      CHECK(p.comparison.Equal());
      if (wireframe) nan_wireframe += test::CountNotColour(p.cpu, list.background);
    }
  }
  CHECK(nan_wireframe > 0);
  RequireNoValidationMessages();
}

TEST_CASE("SwiftShader: denormals as zero, and its rasterizer as a whole, change pixels as the device does",
          "[twin][swiftshader][rules]") {
  const cpu::RasterRules rules = Twin().rules;
  // Denormals as zero: the first square's depth 1e-39 is stored as 0, so the second (depth 0) fails.
  const DrawList denormal = DenormalDepths();
  cpu::RasterRules keeps_denormals = rules;
  keeps_denormals.flush_denormals = false;
  const Image gpu = SwiftShader().Render(denormal);
  CHECK(CompareImages(gpu, cpu::RenderOnCpu(denormal, cpu::CpuOptions{.rules = rules})).Equal());
  CHECK_FALSE(CompareImages(gpu, cpu::RenderOnCpu(denormal, cpu::CpuOptions{.rules = keeps_denormals})).Equal());
  CHECK(test::CountNotColour(gpu, {200, 0, 0}) < test::CountNotColour(gpu, {0, 0, 200}));  // red shows, blue does not
  // The twin sets denormals as zero for its own work only: the caller's MXCSR is as it was.
  const unsigned mxcsr = cpu::FloatControlWord();
  cpu::RenderOnCpu(denormal, cpu::CpuOptions{.threads = 2, .rules = rules});
  CHECK(cpu::FloatControlWord() == mxcsr);
  // SwiftShader's rasterizer against lavapipe's, on scenes of every kind.
  cpu::RasterRules lavapipe = rules;
  lavapipe.rasterizer = cpu::Rasterizer::kLavapipe;
  for (const char* file : {"scenes/lit-gouraud.json", "scenes/catlike-grid.json", "scenes/hard/near-plane.json"}) {
    for (const bool wireframe : {false, true}) {
      INFO(file << (wireframe ? " --wireframe" : ""));
      const DrawList list = BuildDrawList(Shipped(test::SourcePath(file), wireframe));
      const Image device = SwiftShader().Render(list);
      CHECK(CompareImages(device, cpu::RenderOnCpu(list, cpu::CpuOptions{.rules = rules})).Equal());
      CHECK(CompareImages(device, cpu::RenderOnCpu(list, cpu::CpuOptions{.rules = lavapipe})).differing_pixels > 0);
    }
  }
  RequireNoValidationMessages();
}
