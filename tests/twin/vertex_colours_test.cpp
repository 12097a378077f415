// Vertex colours on both backends: lavapipe reads each corner's colour as a vertex attribute and
// the twin as DrawMesh::vertex_colours, with the same k / 255 and the same light, and both
// interpolate them as Gouraud colours; unlit, flat and Gouraud, per draw and instanced, the
// images are identical, and the colours really show.
#include "chain/draw_list.hpp"
#include "image/image_compare.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/image_counts.hpp"
#include "support/lit_scene.hpp"
#include "support/test_support.hpp"
#include "twin_support.hpp"

#include <set>

using namespace twinraster;
using test::DistinctColours;

namespace {

// A lumpy sphere with a colour per vertex drawn twice, so that a run of instances is instanced.
Scene Spheres(Shading shading, bool normals) {
  Scene scene;
  scene.canvas = Canvas{.width = 160, .height = 120, .background = Rgb8{20, 20, 30}};
  scene.viewport = Viewport{.width = 1, .height = 0.75, .distance = 1};
  Model sphere = test::LumpySphere(11, 10, 18, normals, shading);
  for (std::size_t v = 0; v < sphere.vertices.size(); ++v) {
    const auto k = static_cast<std::uint8_t>(v * 37);
    sphere.vertex_colours.push_back(Rgb8{k, static_cast<std::uint8_t>(255 - k), static_cast<std::uint8_t>(v * 11)});
  }
  scene.models.push_back(sphere);
  for (const double x : {-1.2, 1.2}) {
    Instance instance;
    instance.transform.scale = glm::dvec3(1.0, 0.8, 1.0);
    instance.transform.translation = glm::dvec3(x, 0, 4);
    scene.instances.push_back(instance);
  }
  if (shading != Shading::kUnlit) {
    scene.lighting =
        Lighting{.ambient = 0.15,
                 .lights = {Light{.kind = Light::Kind::kDirectional, .vector = {1, 1, -1}, .intensity = 0.6},
                            Light{.kind = Light::Kind::kPoint, .vector = {-2, 1, 1}, .intensity = 0.5}}};
  }
  return scene;
}

const char* Name(Shading shading) {
  return shading == Shading::kFlat ? "flat" : shading == Shading::kGouraud ? "gouraud" : "unlit";
}

}  // namespace

TEST_CASE("Vertex-coloured spheres, unlit, flat and Gouraud: GPU image == CPU image, and the colours show",
          "[twin][vertex-colours]") {
  int judged = 0;
  for (const Shading shading : {Shading::kUnlit, Shading::kFlat, Shading::kGouraud}) {
    for (const bool normals : {false, true}) {
      const Scene scene = Spheres(shading, normals);
      const DrawList list = BuildDrawList(scene);
      REQUIRE(list.meshes[0].vertex_colours.size() == scene.models[0].vertices.size());
      const test::TwinResult r = test::RenderTwins(list);
      INFO(Name(shading) << (normals ? " with normals: " : ": ") << r.Describe());
      CHECK(r.Equal());
      CHECK(test::CountNotColour(r.cpu, scene.canvas.background) > 4000);
      // Interpolated (or, flat, one per triangle) from 190 vertex colours: many shades.
      CHECK(DistinctColours(r.cpu) > 150);
      // Without the vertex colours the triangles' own colours fill them: another picture.
      DrawList without = list;
      without.meshes[0].vertex_colours.clear();
      const test::TwinResult plain = test::RenderTwins(without);
      CHECK(plain.Equal());
      CHECK(CompareImages(r.gpu, plain.gpu).differing_pixels > 4000);
      ++judged;
    }
  }
  CHECK(judged == 6);
  test::RequireNoValidationMessages();
}

TEST_CASE("Random vertex-coloured scenes, unlit, flat and Gouraud: GPU image == CPU image in every one",
          "[twin][vertex-colours][random]") {
  constexpr std::uint32_t kScenes = 1000;
  std::uint32_t failures = 0, drawn = 0, unlit = 0;
  for (std::uint32_t seed = 1; seed <= kScenes; ++seed) {
    const Scene scene = test::RandomVertexColourScene(seed);
    unlit += scene.lighting ? 0 : 1;
    const test::TwinResult r = test::RenderTwins(BuildDrawList(scene));
    drawn += test::CountNotColour(r.cpu, scene.canvas.background) > 0 ? 1 : 0;
    if (r.Equal()) continue;
    ++failures;
    UNSCOPED_INFO("vertex-colour seed " << seed << ": " << r.Describe());
    CHECK(r.Equal());
  }
  REQUIRE(failures == 0);
  CHECK(unlit == kScenes / 3);
  INFO(drawn << " of " << kScenes << " scenes drew something");
  REQUIRE(drawn >= kScenes * 7 / 10);
  test::RequireNoValidationMessages();
}

TEST_CASE("The shipped vertex-colour scenes: GPU image == CPU image, filled and as wireframes in triangle colours",
          "[twin][vertex-colours]") {
  for (const char* file : {"scenes/vertex-colours.json", "scenes/lit-vertex-colours.json"}) {
    Scene scene = LoadScene(test::SourcePath(file));
    const test::TwinResult filled = test::RenderTwins(BuildDrawList(scene));
    INFO(file << ": " << filled.Describe());
    CHECK(filled.Equal());
    CHECK(DistinctColours(filled.cpu) > 1000);  // interpolated, not six flat faces
    scene.wireframe = true;
    const test::TwinResult edges = test::RenderTwins(BuildDrawList(scene));
    INFO("wireframe: " << edges.Describe());
    CHECK(edges.Equal());
    CHECK(DistinctColours(edges.cpu) < 20);  // flat edge colours: no gradient along any line
  }
  test::RequireNoValidationMessages();
}
