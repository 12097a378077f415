// The truth's light in double: hand-computed colours on a square facing the camera, the cap at
// min(I, 1), flat shading lit at the first vertex, Gouraud colours perspective-correct and clipped
// (against the clip-space-linear colour solved by hand at each pixel), and against the twin's.
#include "bench/error_metrics.hpp"
#include "chain/draw_list.hpp"
#include "chain/matrices.hpp"
#include "cpu/cpu_renderer.hpp"
#include "scene/rotation.hpp"
#include "support/catch.hpp"
#include "support/lit_scene.hpp"
#include "truth/truth_renderer.hpp"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <array>
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
  const truth::ExactLight light(scene);
  return truth::RenderTruth(BuildDrawList(scene), truth::ExactClipSpace(scene), &light);
}

int Red(const Image& image, int x, int y) { return image.rgba[4 * (std::size_t(y) * image.width + std::size_t(x))]; }

Light Directional(glm::dvec3 l, double intensity) {
  return Light{.kind = Light::Kind::kDirectional, .vector = l, .intensity = intensity};
}
Light Point(glm::dvec3 p, double intensity) {
  return Light{.kind = Light::Kind::kPoint, .vector = p, .intensity = intensity};
}

// The book's I at world point `p` with unit world normal `n`, written out here rather than taken
// from the chain, so that the truth is checked against the formula itself.
double BookIntensity(const Lighting& lighting, glm::dvec3 p, glm::dvec3 n) {
  double i = lighting.ambient;
  for (const Light& light : lighting.lights) {
    const glm::dvec3 l = light.kind == Light::Kind::kPoint ? light.vector - p : light.vector;
    i += light.intensity * std::max(0.0, glm::dot(n, l)) / glm::length(l);
  }
  return i;
}

// Each corner's colour (0..1) of triangle `t` of the scene's only instance, by hand: world
// position M·p, world normal (M's upper 3x3)⁻ᵀ·n renormalised, colour = base/255 · min(I, 1).
// `normal(k)` is corner k's model-space normal.
template <class Normal>
std::array<glm::dvec3, 3> HandCornerColours(const Scene& scene, std::size_t t, Normal normal) {
  const Model& model = scene.models[0];
  const glm::dmat4 m = ModelMatrix(scene.instances[0].transform);
  const glm::dmat3 n_matrix = glm::transpose(glm::inverse(glm::dmat3(m)));
  const Rgb8 base = model.triangles[t].colour;
  std::array<glm::dvec3, 3> colours;
  for (std::size_t k = 0; k < 3; ++k) {
    const glm::dvec3 p(m * glm::dvec4(model.vertices[model.triangles[t].v[k]], 1.0));
    const glm::dvec3 n = glm::normalize(n_matrix * normal(k));
    colours[k] = glm::dvec3(base.r, base.g, base.b) / 255.0 * std::min(BookIntensity(*scene.lighting, p, n), 1.0);
  }
  return colours;
}

// Weights λ (summing to 1) of the point Σ λ_i clip_i that lands on the pixel centre (px, py):
// Σ λ_i (x_i - xn w_i) = 0, Σ λ_i (y_i - yn w_i) = 0. Colour linear in clip space is Σ λ_i c_i,
// whatever clipping did on the way. glm's dmat3 is column-major: a[column][row].
glm::dvec3 ClipWeights(const std::array<glm::dvec4, 3>& clip, int px, int py, std::uint32_t width,
                       std::uint32_t height) {
  const double xn = 2.0 * (px + 0.5) / width - 1.0, yn = 2.0 * (py + 0.5) / height - 1.0;
  glm::dmat3 a;
  for (std::size_t i = 0; i < 3; ++i) {
    a[static_cast<glm::length_t>(i)] = glm::dvec3(clip[i].x - xn * clip[i].w, clip[i].y - yn * clip[i].w, 1.0);
  }
  return glm::inverse(a) * glm::dvec3(0, 0, 1);
}

// The same weights for colours interpolated linearly on the screen (not perspective-correct).
glm::dvec3 ScreenWeights(const std::array<glm::dvec4, 3>& clip, int px, int py, std::uint32_t width,
                         std::uint32_t height) {
  std::array<glm::dvec4, 3> projected;
  for (std::size_t i = 0; i < 3; ++i) projected[i] = glm::dvec4(clip[i].x / clip[i].w, clip[i].y / clip[i].w, 0.0, 1.0);
  return ClipWeights(projected, px, py, width, height);
}

const std::uint8_t* Pixel(const Image& image, std::size_t p) { return &image.rgba[4 * p]; }

// Whether byte `b` is the rounding of colour channel c (0..1): within 1/2 of c·255, ties either way.
bool RoundsTo(double c, int b) { return std::abs(std::clamp(c, 0.0, 1.0) * 255.0 - b) <= 0.5 + 1e-7; }

struct GouraudCheck {
  std::uint64_t pixels = 0;        // covered pixels checked against the clip-space-linear colour
  double worst_screen_linear = 0;  // how far (of 255) colours linear on the screen would be
};

// Every pixel of the truth showing one of the only instance's triangles has the colour Σ λ_i c_i
// of the hand-computed corner colours, λ solved in clip space at its centre.
template <class Normal>
GouraudCheck CheckGouraudPixels(const Scene& scene, Normal normal_of) {
  const DrawList list = BuildDrawList(scene);
  const truth::ExactClipPositions clip = truth::ExactClipSpace(scene);
  const truth::ExactLight light(scene);
  const truth::TruthImage truth = truth::RenderTruthSurfaces(list, clip, &light);
  const Model& model = scene.models[0];
  GouraudCheck check;
  for (std::size_t p = 0; p < truth.surfaces.size(); ++p) {
    if (truth.surfaces[p] == 0) continue;
    const std::size_t t = truth.surfaces[p] - 1;
    REQUIRE(t < model.triangles.size());
    const std::array<glm::dvec4, 3> corners = {clip[0][model.triangles[t].v[0]], clip[0][model.triangles[t].v[1]],
                                               clip[0][model.triangles[t].v[2]]};
    const int px = static_cast<int>(p % list.width), py = static_cast<int>(p / list.width);
    const glm::dvec3 lambda = ClipWeights(corners, px, py, list.width, list.height);
    INFO("pixel " << px << ", " << py << ", triangle " << t);
    REQUIRE(std::min({lambda.x, lambda.y, lambda.z}) > -1e-9);  // the centre is on the triangle it shows
    const std::array<glm::dvec3, 3> c = HandCornerColours(scene, t, [&](std::size_t k) { return normal_of(t, k); });
    const glm::dvec3 expected = lambda.x * c[0] + lambda.y * c[1] + lambda.z * c[2];
    const std::uint8_t* shown = Pixel(truth.image, p);
    CHECK(RoundsTo(expected.x, shown[0]));
    CHECK(RoundsTo(expected.y, shown[1]));
    CHECK(RoundsTo(expected.z, shown[2]));
    if (std::min({corners[0].w, corners[1].w, corners[2].w}) > 0) {
      const glm::dvec3 mu = ScreenWeights(corners, px, py, list.width, list.height);
      const glm::dvec3 screen = mu.x * c[0] + mu.y * c[1] + mu.z * c[2];
      check.worst_screen_linear = std::max(check.worst_screen_linear, 255 * glm::length(screen - expected));
    }
    ++check.pixels;
  }
  return check;
}

}  // namespace

TEST_CASE("Truth light: ambient plus a directional light facing the square, and the cap at 1", "[truth][lighting]") {
  // I = 0.2 + 0.6 · 1 = 0.8: 255 · 0.8 = 204.
  CHECK(Red(Truth(FacingSquare({.ambient = 0.2, .lights = {Directional({0, 0, -1}, 0.6)}}, Shading::kFlat)), 32, 32) ==
        204);
  // Ambient alone: 255 · 0.4 = 102; a light from behind adds nothing.
  CHECK(Red(Truth(FacingSquare({.ambient = 0.4, .lights = {Directional({0, 0, 1}, 0.9)}}, Shading::kGouraud)), 32,
            32) == 102);
  // A light at 60 degrees: n·l/|l| = cos 60° = 0.5 whatever |l|; I = 0.5 · 0.8 = 0.4, 102.
  const glm::dvec3 sixty(0, std::sin(std::acos(0.5)) * 7, -0.5 * 7);
  CHECK(Red(Truth(FacingSquare({.ambient = 0, .lights = {Directional(sixty, 0.8)}}, Shading::kFlat)), 32, 32) == 102);
  // I = 0.5 + 0.8 = 1.3 is capped at 1: white, not brighter.
  CHECK(Red(Truth(FacingSquare({.ambient = 0.5, .lights = {Directional({0, 0, -1}, 0.8)}}, Shading::kFlat)), 32, 32) ==
        255);
}

TEST_CASE("Truth light: flat shading lights the triangle at its first vertex, Gouraud at every corner",
          "[truth][lighting]") {
  // A point light straight in front of corner 0 of both triangles, (-1, -1, 5) in world space.
  const Lighting point{.ambient = 0,
                       .lights = {Light{.kind = Light::Kind::kPoint, .vector = {-1, -1, 3}, .intensity = 1}}};
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
    const truth::ExactLight light(scene);
    const bench::ColourError error =
        bench::SameSurfaceColourError(cpu::RenderOnCpu(list), cpu::RenderOnCpu(*bench::SurfaceList(list)),
                                      truth::RenderTruthSurfaces(list, truth::ExactClipSpace(scene), &light));
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
  CHECK_THROWS_WITH(truth::RenderTruth(BuildDrawList(lit), truth::ExactClipSpace(lit)), HasSubstring("no light"));
  Scene unlit = lit;
  unlit.lighting.reset();
  unlit.models[0].shading = Shading::kUnlit;
  CHECK(Red(truth::RenderTruth(BuildDrawList(unlit), truth::ExactClipSpace(unlit)), 32, 32) == 255);  // its own white
}

TEST_CASE("Truth light: a flat triangle takes its first corner's light from a point light, not its centroid's",
          "[truth][lighting]") {
  // Two triangles whose first corners are opposite corners of the square, (-1, -1, 5) and (1, 1, 5),
  // both facing the camera; a point light off-centre in front; a colour that is not grey.
  Scene scene = FacingSquare({.ambient = 0.1, .lights = {Point({0.3, -0.4, 3}, 0.7)}}, Shading::kFlat);
  scene.models[0].triangles = {Triangle{{0, 2, 1}, Rgb8{200, 150, 100}}, Triangle{{2, 0, 3}, Rgb8{200, 150, 100}}};
  const truth::ExactLight light(scene);
  const truth::TruthImage truth =
      truth::RenderTruthSurfaces(BuildDrawList(scene), truth::ExactClipSpace(scene), &light);
  // By hand: the normal is (0, 0, -1). Corner (-1, -1, 5): l = (1.3, 0.6, -2), n·l = 2,
  // |l| = √6.05, I = 0.1 + 0.7 · 2/√6.05 = 0.66918; corner (1, 1, 5): l = (-0.7, -1.4, -2),
  // |l| = √6.45, I = 0.1 + 0.7 · 2/√6.45 = 0.65127.
  const double first[2] = {0.1 + 0.7 * 2 / std::sqrt(6.05), 0.1 + 0.7 * 2 / std::sqrt(6.45)};
  // Lit at its centroid, triangle 0 would be (1/3, -1/3, 5): I = 0.1 + 0.7 · 2/|(-1/30, -1/15, -2)| = 0.7992.
  const double centroid0 = 0.1 + 0.7 * 2 / glm::length(glm::dvec3(-1.0 / 30, -1.0 / 15, -2));
  REQUIRE(std::lround(200 * centroid0) != std::lround(200 * first[0]));  // the two rules tell apart
  std::uint64_t counted[2] = {0, 0};
  for (std::size_t p = 0; p < truth.surfaces.size(); ++p) {
    if (truth.surfaces[p] == 0) continue;
    const std::size_t t = truth.surfaces[p] - 1;
    REQUIRE(t < 2);
    INFO("pixel " << p << ", triangle " << t);
    const std::uint8_t* shown = Pixel(truth.image, p);
    CHECK(RoundsTo(200.0 / 255 * first[t], shown[0]));  // 134 and 130
    CHECK(RoundsTo(150.0 / 255 * first[t], shown[1]));
    CHECK(RoundsTo(100.0 / 255 * first[t], shown[2]));
    ++counted[t];
  }
  CHECK(counted[0] > 300);  // the square is about 25.6 pixels wide
  CHECK(counted[1] > 300);
  CHECK(int{Pixel(truth.image, 40 * 64 + 40)[0]} == 134);  // inside triangle 0 (lower right: +y is down)
}

TEST_CASE("Truth light: Gouraud is perspective-correct, with vn through the normal matrix under a non-uniform scale",
          "[truth][lighting]") {
  // One triangle receding from z = 2 to z = 8, its corners' own normals (as an OBJ's vn),
  // scaled non-uniformly and turned; a point light, a directional light and ambient.
  Scene scene;
  scene.canvas = Canvas{.width = 128, .height = 128, .background = Rgb8{0, 0, 0}};
  Model model;
  model.name = "receding";
  model.shading = Shading::kGouraud;
  model.vertices = {glm::dvec3(-0.55, -1.0, -2.5), glm::dvec3(2.3, -2.4, 2.5), glm::dvec3(0.0, 3.0, 0.8)};
  model.normals = {glm::dvec3(0.1, 0.1, -1), glm::dvec3(1.2, 0, -0.5), glm::dvec3(0, -1.5, -0.3)};
  model.triangles = {Triangle{{0, 1, 2}, Rgb8{230, 180, 90}}};
  model.triangle_normals = {{0, 1, 2}};
  scene.models.push_back(model);
  Instance instance;
  instance.transform.scale = glm::dvec3(1.5, 0.8, 1.2);
  instance.transform.rotation = Rotation(glm::dvec3(0, 1, 0), 6);
  instance.transform.translation = glm::dvec3(0, 0, 5);
  scene.instances.push_back(instance);
  scene.lighting = Lighting{.ambient = 0.05, .lights = {Point({0.5, 0.5, 1}, 0.2), Directional({0.1, -0.1, -1}, 0.7)}};

  const auto normal = [&](std::size_t, std::size_t k) { return model.normals[k]; };
  // The corners differ enough that interpolation shows.
  const std::array<glm::dvec3, 3> c = HandCornerColours(scene, 0, [&](std::size_t k) { return normal(0, k); });
  REQUIRE(std::max({glm::length(c[0] - c[1]), glm::length(c[1] - c[2]), glm::length(c[0] - c[2])}) > 0.3);
  const GouraudCheck check = CheckGouraudPixels(scene, normal);
  CHECK(check.pixels > 3000);
  // Colours linear on the screen would be visibly off: the test can tell the two apart.
  CHECK(check.worst_screen_linear > 10);
}

TEST_CASE("Truth light: a Gouraud floor cut by the near plane and the screen's sides keeps clip-space-linear colours",
          "[truth][lighting]") {
  // A floor triangle at y = -1 from behind the camera (z = -5, w < 0) to z = 40, far wider than
  // the view: clipped against the near plane and both sides, its colours clipped with it.
  Scene scene;
  scene.canvas = Canvas{.width = 96, .height = 64, .background = Rgb8{0, 0, 0}};
  scene.viewport = Viewport{.width = 1.5, .height = 1.0, .distance = 1.0};
  Model model;
  model.name = "floor";
  model.shading = Shading::kGouraud;
  model.vertices = {glm::dvec3(-30, -1, -5), glm::dvec3(0, -1, 40), glm::dvec3(30, -1, -5)};
  model.normals = {glm::dvec3(0.5, 1, 0), glm::dvec3(0, 1, -0.7), glm::dvec3(-0.6, 1, 0.2)};
  model.triangles = {Triangle{{0, 1, 2}, Rgb8{255, 255, 255}}};
  model.triangle_normals = {{0, 1, 2}};
  scene.models.push_back(model);
  scene.instances.push_back(Instance{});
  scene.lighting = Lighting{.ambient = 0.05, .lights = {Directional({0.2, 1, 0.3}, 0.5), Point({0, 0.5, 4}, 0.8)}};

  const auto normal = [&](std::size_t, std::size_t k) { return model.normals[k]; };
  const truth::ExactClipPositions clip = truth::ExactClipSpace(scene);
  REQUIRE(clip[0][0].w < 0);  // behind the camera: the near plane must cut
  const GouraudCheck check = CheckGouraudPixels(scene, normal);
  CHECK(check.pixels > 1000);  // the lower half of the picture, about 3000 pixels
}
