// Lit scenes on both backends: the twin lights each vertex with the vertex shader's float
// operations and interpolates Gouraud colours as lavapipe does, so the images are identical.
#include "chain/draw_list.hpp"
#include "chain/light_trace.hpp"
#include "chain/matrices.hpp"
#include "chain/normals.hpp"
#include "cpu/cpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/lit_scene.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <set>

using namespace twinraster;
using test::DistinctColours;

namespace {}  // namespace

TEST_CASE("Lit spheres, flat and Gouraud: GPU image == CPU image", "[twin][lighting]") {
  for (const Shading shading : {Shading::kFlat, Shading::kGouraud}) {
    for (const bool normals : {false, true}) {
      Scene scene;
      scene.canvas = Canvas{.width = 160, .height = 120, .background = Rgb8{20, 20, 30}};
      scene.viewport = Viewport{.width = 1, .height = 0.75, .distance = 1};
      scene.models.push_back(test::LumpySphere(7, 16, 24, normals, shading));
      Instance instance;
      instance.transform.scale = glm::dvec3(1.5, 0.8, 1.0);
      instance.transform.translation = glm::dvec3(0, 0, 4);
      scene.instances.push_back(instance);
      scene.lighting =
          Lighting{.ambient = 0.1,
                   .lights = {Light{.kind = Light::Kind::kDirectional, .vector = {1, 1, -1}, .intensity = 0.6},
                              Light{.kind = Light::Kind::kPoint, .vector = {-2, 1, 1}, .intensity = 0.5}}};
      const DrawList list = BuildDrawList(scene);
      REQUIRE(list.lighting.has_value());
      const test::TwinResult r = test::RenderTwins(list);
      INFO((shading == Shading::kFlat ? "flat" : "gouraud") << (normals ? " with normals: " : ": ") << r.Describe());
      CHECK(r.Equal());
      // The light shows: far more shades than the sphere's few base colours.
      CHECK(DistinctColours(r.cpu) > 40);
    }
  }
  test::RequireNoValidationMessages();
}

TEST_CASE("Random lit scenes: GPU image == CPU image in every one", "[twin][lighting][random]") {
  test::SharedGpu(gpu::Instancing::kNever);
  test::SharedGpu(gpu::Instancing::kAlways);
  constexpr std::uint32_t kScenes = 1000;
  std::uint32_t failures = 0, drawn = 0;
  for (std::uint32_t seed = 1; seed <= kScenes; ++seed) {
    const Scene scene = test::RandomLitScene(seed);
    const test::TwinResult r = test::RenderTwins(BuildDrawList(scene));
    drawn += test::CountNotColour(r.cpu, scene.canvas.background) > 0 ? 1 : 0;
    if (r.Equal()) continue;
    ++failures;
    UNSCOPED_INFO("lit seed " << seed << ": " << r.Describe());
    CHECK(r.Equal());
  }
  REQUIRE(failures == 0);
  INFO(drawn << " of " << kScenes << " scenes drew something");
  REQUIRE(drawn >= kScenes * 7 / 10);
  test::RequireNoValidationMessages();
}

namespace {

// docs/normals.md's example: a square in the plane z = x, facing the camera, stretched 2x along x
// (so its plane becomes z = x/2), lit by a headlight l = (0, 0, -1). The true normal is
// (1, 0, -2)/√5 and gives I = 2/√5 = 0.894; M_Model itself would tilt it to (2, 0, -1)/√5, I = 0.447.
Scene StretchedSquare() {
  Scene scene;
  scene.canvas = Canvas{.width = 64, .height = 64, .background = Rgb8{0, 0, 0}};
  Model square;
  square.name = "square";
  square.vertices = {glm::dvec3(-1, -1, -1), glm::dvec3(1, -1, 1), glm::dvec3(1, 1, 1), glm::dvec3(-1, 1, -1)};
  square.triangles = {Triangle{{0, 2, 1}, Rgb8{255, 255, 255}}, Triangle{{0, 3, 2}, Rgb8{255, 255, 255}}};
  square.shading = Shading::kFlat;
  scene.models.push_back(square);
  Instance instance;
  instance.transform.scale = glm::dvec3(2, 1, 1);
  instance.transform.translation = glm::dvec3(0, 0, 6);
  scene.instances.push_back(instance);
  scene.lighting = Lighting{.ambient = 0,
                            .lights = {Light{.kind = Light::Kind::kDirectional, .vector = {0, 0, -1}, .intensity = 1}}};
  return scene;
}

std::uint8_t RedAt(const Image& image, std::uint32_t x, std::uint32_t y) {
  return image.rgba[4 * (std::size_t{y} * image.width + x)];
}

}  // namespace

TEST_CASE("The normal matrix lights a stretched surface right where M_Model itself is visibly wrong",
          "[twin][lighting][normals]") {
  const Scene scene = StretchedSquare();
  DrawList right = BuildDrawList(scene);
  REQUIRE(right.lighting.has_value());
  // The wrong way: normals through M_Model's own upper 3x3.
  DrawList wrong = right;
  wrong.lighting->instances[0].normal = glm::mat3(glm::dmat3(ModelMatrix(scene.instances[0].transform)));

  const test::TwinResult r = test::RenderTwins(right);
  INFO(r.Describe());
  REQUIRE(r.Equal());
  const Image wrong_image = cpu::RenderOnCpu(wrong, test::TwinOptions(cpu::CpuOptions{1}));
  // The centre pixel: 255 · 2/√5 = 228.1 with the inverse transpose, 255 · 1/√5 = 114.0 with M.
  CHECK(int{RedAt(r.cpu, 32, 32)} == 228);
  CHECK(int{RedAt(wrong_image, 32, 32)} == 114);

  // explain's trace says the same, in double.
  const LightTrace trace =
      TraceLight(*scene.lighting, ModelMatrix(scene.instances[0].transform),
                 *NormalMatrix(ModelMatrix(scene.instances[0].transform)), scene.models[0].vertices[0],
                 glm::normalize(glm::dvec3(1, 0, -1)), Rgb8{255, 255, 255});
  CHECK(trace.intensity == Approx(2 / std::sqrt(5.0)).margin(1e-12));
  CHECK(trace.wrong_normal.x == Approx(2 / std::sqrt(5.0)).margin(1e-12));
  CHECK(trace.unit_normal.x == Approx(1 / std::sqrt(5.0)).margin(1e-12));
}

TEST_CASE("The normal matrix: inverse transpose of M_Model's upper 3x3", "[chain][lighting][normals]") {
  const auto n = [](const Transform& t) { return NormalMatrix(ModelMatrix(t)); };
  Transform stretch;
  stretch.scale = glm::dvec3(2, 4, 0.5);
  stretch.translation = glm::dvec3(7, 8, 9);  // translation plays no part
  REQUIRE(n(stretch).has_value());
  CHECK(*n(stretch) == glm::dmat3(glm::dvec3(0.5, 0, 0), glm::dvec3(0, 0.25, 0), glm::dvec3(0, 0, 2)));
  Transform turn;
  turn.rotation = Rotation(glm::dvec3(0, 1, 0), 30);
  const glm::dmat3 r = *n(turn);  // a rotation is its own inverse transpose
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) CHECK(r[c][k] == Approx(turn.rotation[c][k]).margin(1e-15));
  Transform mirror;
  mirror.scale = glm::dvec3(-1, 1, 1);
  CHECK(*n(mirror) == glm::dmat3(glm::dvec3(-1, 0, 0), glm::dvec3(0, 1, 0), glm::dvec3(0, 0, 1)));
  Transform flat;
  flat.scale = glm::dvec3(1, 0, 1);
  CHECK_FALSE(n(flat).has_value());
  // Invertible in exact arithmetic, but the determinant (1e-330) underflows double, and at 1e-40
  // the inverse (1e40) is past float's range, where the renderers take it: none, as for a zero.
  Transform tiny;
  tiny.scale = glm::dvec3(1e-110);
  CHECK_FALSE(n(tiny).has_value());
  tiny.scale = glm::dvec3(1, 1e-40, 1);
  CHECK_FALSE(n(tiny).has_value());
  tiny.scale = glm::dvec3(1e-30);  // the smallest the loaders accept: 1e30, within float's range
  REQUIRE(n(tiny).has_value());
  CHECK((*n(tiny))[1][1] == Approx(1e30).epsilon(1e-15));
}

TEST_CASE("A lit scene past one LitInstance range: lavapipe draws it range by range, still == the twin",
          "[twin][lighting][large]") {
  // 1,050,000 lit cubes: more than gpu::kLitInstancesPerRange (2^20), so both the per-draw and the
  // instanced path cross a range's end in the middle of a run of instances.
  Scene scene = LoadScene(test::SourcePath("scenes/one-million-cubes.json"));
  REQUIRE(scene.grids.size() == 1);
  Instance cube = scene.instances[scene.grids[0].first];
  scene.instances.clear();
  scene.grids.clear();
  for (int i = 0; i < 105; ++i)
    for (int j = 0; j < 100; ++j)
      for (int k = 0; k < 100; ++k) {
        Instance copy = cube;
        copy.transform.translation += glm::dvec3(i - 52, j - 49.5, k - 49.5);
        scene.instances.push_back(copy);
      }
  scene.canvas.width = 480;
  scene.canvas.height = 270;
  scene.models[0].shading = Shading::kFlat;
  scene.lighting = Lighting{
      .ambient = 0.2, .lights = {Light{.kind = Light::Kind::kDirectional, .vector = {1, 2, -3}, .intensity = 0.8}}};
  const DrawList list = BuildDrawList(scene);
  REQUIRE(list.draws.size() > (std::size_t{1} << 20));
  const test::TwinResult r = test::RenderTwins(list);
  INFO(r.Describe());
  REQUIRE(r.Equal());
  // And the light is really there: the same cubes unlit are another picture.
  scene.lighting.reset();
  scene.models[0].shading = Shading::kUnlit;
  REQUIRE(CompareImages(r.cpu, cpu::RenderOnCpu(BuildDrawList(scene), test::TwinOptions())).differing_pixels > 10000);
  test::RequireNoValidationMessages();
}
