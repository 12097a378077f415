// Lit scenes on both backends: the twin lights each vertex with the vertex shader's float
// operations and interpolates Gouraud colours as lavapipe does, so the images are identical.
#include "chain/draw_list.hpp"
#include "support/image_counts.hpp"
#include "lit_scene.hpp"
#include "twin_support.hpp"

#include <catch2/catch.hpp>

#include <set>

using namespace twinraster;

namespace {

// The number of distinct colours in an image: a lit sphere has many, an unlit one a few.
std::size_t DistinctColours(const Image& image) {
  std::set<std::uint32_t> colours;
  for (std::size_t i = 0; i + 3 < image.rgba.size(); i += 4) {
    colours.insert(std::uint32_t{image.rgba[i]} | std::uint32_t{image.rgba[i + 1]} << 8 |
                   std::uint32_t{image.rgba[i + 2]} << 16);
  }
  return colours.size();
}

}  // namespace

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
      scene.lighting = Lighting{.ambient = 0.1,
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
