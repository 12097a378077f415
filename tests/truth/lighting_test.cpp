// The truth's light in double: hand-computed colours on a square facing the camera, the cap at
// min(I, 1), flat shading lit at the first vertex, and Gouraud colours against the twin's.
#include "bench/error_metrics.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "support/lit_scene.hpp"
#include "truth/truth_renderer.hpp"

#include <catch2/catch.hpp>

#include <glm/geometric.hpp>

#include <cmath>

using namespace twinraster;

namespace {

// A white square at z = 5 facing the camera (face normal (0, 0, -1)), filling the middle of a
// 64x64 canvas; lit as given.
Scene FacingSquare(const Lighting& lighting, Shading shading) {
  Scene scene;
  scene.canvas = Canvas{.width = 64, .height = 64, .background = Rgb8{0, 0, 0}};
  Model square;
  square.name = "square";
  square.shading = shading;
  square.vertices = {glm::dvec3(-1, -1, 0), glm::dvec3(1, -1, 0), glm::dvec3(1, 1, 0), glm::dvec3(-1, 1, 0)};
  square.triangles = {Triangle{{0, 2, 1}, Rgb8{255, 255, 255}}, Triangle{{0, 3, 2}, Rgb8{255, 255, 255}}};
  scene.models.push_back(square);
  Instance instance;
  instance.transform.translation = glm::dvec3(0, 0, 5);
  scene.instances.push_back(instance);
  scene.lighting = lighting;
  return scene;
}

Image Truth(const Scene& scene) {
  const ExactLight light(scene);
  return RenderTruth(BuildDrawList(scene), ExactClipSpace(scene), &light);
}

int Red(const Image& image, int x, int y) { return image.rgba[4 * (std::size_t(y) * image.width + std::size_t(x))]; }

Light Directional(glm::dvec3 l, double intensity) { return Light{.kind = Light::Kind::kDirectional, .vector = l, .intensity = intensity}; }

}  // namespace

TEST_CASE("Truth light: ambient plus a directional light facing the square, and the cap at 1", "[truth][lighting]") {
  // I = 0.2 + 0.6 · 1 = 0.8: 255 · 0.8 = 204.
  CHECK(Red(Truth(FacingSquare({.ambient = 0.2, .lights = {Directional({0, 0, -1}, 0.6)}}, Shading::kFlat)), 32, 32) == 204);
  // Ambient alone: 255 · 0.4 = 102; a light from behind adds nothing.
  CHECK(Red(Truth(FacingSquare({.ambient = 0.4, .lights = {Directional({0, 0, 1}, 0.9)}}, Shading::kGouraud)), 32, 32) == 102);
  // A light at 60 degrees: n·l/|l| = cos 60° = 0.5 whatever |l|; I = 0.5 · 0.8 = 0.4, 102.
  const glm::dvec3 sixty(0, std::sin(std::acos(0.5)) * 7, -0.5 * 7);
  CHECK(Red(Truth(FacingSquare({.ambient = 0, .lights = {Directional(sixty, 0.8)}}, Shading::kFlat)), 32, 32) == 102);
  // I = 0.5 + 0.8 = 1.3 is capped at 1: white, not brighter.
  CHECK(Red(Truth(FacingSquare({.ambient = 0.5, .lights = {Directional({0, 0, -1}, 0.8)}}, Shading::kFlat)), 32, 32) == 255);
}

TEST_CASE("Truth light: flat shading lights the triangle at its first vertex, Gouraud at every corner", "[truth][lighting]") {
  // A point light straight in front of corner 0 of both triangles, (-1, -1, 5) in world space.
  const Lighting point{.ambient = 0, .lights = {Light{.kind = Light::Kind::kPoint, .vector = {-1, -1, 3}, .intensity = 1}}};
  const Image flat = Truth(FacingSquare(point, Shading::kFlat));
  // Lit at corner 0 only, where l = (0, 0, -2) is along the normal: I = 1 over the whole triangle.
  CHECK(Red(flat, 32, 40) == 255);
  CHECK(Red(flat, 40, 33) == 255);
  // Gouraud: the far corner (1, 1, 5) sees l = (-2, -2, -2), n·l/|l| = 1/√3; the centre of the
  // square lies on the diagonal between corners 0 and 2, halfway in screen space (both at z = 5,
  // so perspective changes nothing): (1 + 1/√3) / 2 = 0.7887 of 255 = 201.1, so 201.
  const Image gouraud = Truth(FacingSquare(point, Shading::kGouraud));
  const double expected = 255 * (1 + 1 / std::sqrt(3.0)) / 2;
  CHECK(std::abs(Red(gouraud, 31, 32) - expected) < 4);  // a pixel off the exact centre
}

TEST_CASE("Truth light against the twin: random lit scenes agree within 1 triangle by triangle", "[truth][lighting]") {
  std::uint64_t compared = 0;
  int worst = 0;
  for (std::uint32_t seed = 1; seed <= 60; ++seed) {
    const Scene scene = test::RandomLitScene(seed);
    const DrawList list = BuildDrawList(scene);
    const ExactLight light(scene);
    const ColourError error = SameSurfaceColourError(RenderOnCpu(list), RenderOnCpu(*SurfaceList(list)),
                                                     RenderTruthSurfaces(list, ExactClipSpace(scene), &light));
    INFO("seed " << seed);
    CHECK(error.max_channel <= 1);
    worst = std::max(worst, error.max_channel);
    compared += error.pixels;
  }
  INFO(compared << " pixels compared, worst " << worst);
  REQUIRE(compared > 100000);
}

TEST_CASE("Truth light: a lit list without the light is refused, an unlit list needs none", "[truth][lighting]") {
  const Scene lit = FacingSquare({.ambient = 0.2, .lights = {}}, Shading::kFlat);
  CHECK_THROWS_WITH(RenderTruth(BuildDrawList(lit), ExactClipSpace(lit)), Catch::Contains("no light"));
  Scene unlit = lit;
  unlit.lighting.reset();
  unlit.models[0].shading = Shading::kUnlit;
  CHECK(Red(RenderTruth(BuildDrawList(unlit), ExactClipSpace(unlit)), 32, 32) == 255);  // its own white
}
