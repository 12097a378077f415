// Watertightness on both backends: triangles that share edges cover every pixel exactly once.
// Each triangle is drawn alone and the covered pixels are counted, so a pixel claimed by two
// neighbours (or by none) shows up as a count of 2 (or 0).
#include "chain/draw_list.hpp"
#include "chain/matrices.hpp"
#include "cpu/cpu_renderer.hpp"
#include "support/catch.hpp"
#include "twin_support.hpp"

#include <cmath>
#include <numbers>
#include <random>

using namespace twinraster;

namespace {

constexpr Rgb8 kBackground{0, 0, 0};

struct Coverage {
  std::uint32_t width = 0, height = 0;
  std::vector<int> gpu, cpu;  // how many triangles covered each pixel
};

// Draws each triangle of `mesh` by itself with matrix `f`, on both backends, counting coverage.
// `count_it` picks which triangles count (all of them, or the front faces only, ...).
template <typename Predicate>
Coverage CountCoverage(std::uint32_t w, std::uint32_t h, const DrawMesh& mesh, const glm::mat4& f, Predicate count_it) {
  Coverage c{w, h, std::vector<int>(std::size_t{w} * h), std::vector<int>(std::size_t{w} * h)};
  for (std::size_t t = 0; t < mesh.triangles.size(); ++t) {
    if (!count_it(t)) continue;
    DrawList one;
    one.width = w;
    one.height = h;
    one.background = kBackground;
    DrawMesh single;
    for (std::uint32_t v : mesh.triangles[t]) single.positions.push_back(mesh.positions[v]);
    single.triangles = {{0, 1, 2}};
    single.colours = {Rgb8{255, 255, 255}};
    one.meshes = {single};
    one.draws = {DrawCall{0, f}};
    const Image gpu = test::SharedGpu().Render(one);
    const Image cpu = cpu::RenderOnCpu(one, test::TwinOptions());
    for (std::size_t i = 0; i < c.gpu.size(); ++i) {
      c.gpu[i] += gpu.rgba[i * 4] != 0 ? 1 : 0;
      c.cpu[i] += cpu.rgba[i * 4] != 0 ? 1 : 0;
    }
  }
  return c;
}

// Signed distance-like test: is (x, y) inside the closed polygon, and how far from its outline?
double DistanceToSegment(double px, double py, glm::dvec2 a, glm::dvec2 b) {
  const glm::dvec2 ab = b - a, ap = glm::dvec2(px, py) - a;
  const double t = std::clamp(glm::dot(ap, ab) / glm::dot(ab, ab), 0.0, 1.0);
  return glm::length(ap - t * ab);
}

bool InsidePolygon(double px, double py, const std::vector<glm::dvec2>& poly) {
  bool inside = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    if ((poly[i].y > py) != (poly[j].y > py) &&
        px < (poly[j].x - poly[i].x) * (py - poly[i].y) / (poly[j].y - poly[i].y) + poly[i].x) {
      inside = !inside;
    }
  }
  return inside;
}

}  // namespace

TEST_CASE("Watertight: a triangle fan covers each pixel inside its outline exactly once", "[twin][watertight]") {
  const std::uint32_t w = 97, h = 83;
  std::mt19937 random(7);
  for (int round = 0; round < 4; ++round) {
    // A star-shaped polygon around a centre at an arbitrary sub-pixel position (in round 0, exactly
    // on a pixel centre, so that every spoke passes through pixel centres).
    std::uniform_real_distribution<double> jitter(0, 1), radius(15, 38);
    // (Drawn one after the other: the order of a call's arguments differs between compilers.)
    const double jx = jitter(random), jy = jitter(random);
    const glm::dvec2 centre = round == 0 ? glm::dvec2(48.5, 41.5) : glm::dvec2(40 + 16 * jx, 35 + 12 * jy);
    const int spokes = round == 0 ? 16 : 24;
    std::vector<glm::dvec2> outline;
    for (int i = 0; i < spokes; ++i) {
      const double a = 2 * std::numbers::pi * i / spokes;
      const double r = round == 0 ? 32 : radius(random);
      outline.push_back(centre + r * glm::dvec2(std::cos(a), std::sin(a)));
    }
    // Framebuffer pixels to NDC with w = 1, so the identity matrix draws them where they are.
    DrawMesh fan;
    const auto ndc = [&](glm::dvec2 p) { return glm::vec3(float(p.x / w * 2 - 1), float(p.y / h * 2 - 1), 0.5f); };
    fan.positions.push_back(ndc(centre));
    for (const glm::dvec2& p : outline) fan.positions.push_back(ndc(p));
    for (int i = 0; i < spokes; ++i) {
      fan.triangles.push_back({0, std::uint32_t(1 + i), std::uint32_t(1 + (i + 1) % spokes)});
      fan.colours.push_back({255, 255, 255});
    }
    // The outline as the renderers see it: the float positions, back in pixels.
    std::vector<glm::dvec2> exact;
    for (std::size_t i = 1; i < fan.positions.size(); ++i)
      exact.push_back({(double(fan.positions[i].x) + 1) * w / 2, (double(fan.positions[i].y) + 1) * h / 2});

    const Coverage c = CountCoverage(w, h, fan, glm::mat4(1.0f), [](std::size_t) { return true; });
    std::size_t inside_pixels = 0;
    for (std::uint32_t y = 0; y < h; ++y)
      for (std::uint32_t x = 0; x < w; ++x) {
        const double px = x + 0.5, py = y + 0.5;
        double to_outline = 1e9;
        for (std::size_t i = 0; i < exact.size(); ++i)
          to_outline = std::min(to_outline, DistanceToSegment(px, py, exact[i], exact[(i + 1) % exact.size()]));
        const std::size_t i = std::size_t{y} * w + x;
        INFO("round " << round << ", pixel (" << x << ", " << y << ")");
        REQUIRE(c.gpu[i] == c.cpu[i]);
        REQUIRE(c.cpu[i] <= 1);
        // On the outline the fill rule may go either way, and snapping to 1/256 pixel moves an
        // edge by up to that much.
        if (to_outline < 1.0 / 256) continue;
        const int expected = InsidePolygon(px, py, exact) ? 1 : 0;
        REQUIRE(c.cpu[i] == expected);
        inside_pixels += std::size_t(expected);
      }
    REQUIRE(inside_pixels > 1000);
  }
  test::RequireNoValidationMessages();
}

TEST_CASE("Watertight: a closed convex mesh covers each pixel once with front faces and once with back faces",
          "[twin][watertight]") {
  // A UV sphere in perspective, turned at random: every pixel inside the silhouette lies under
  // exactly one front face and exactly one back face, and nothing lies under two of either.
  DrawMesh sphere;
  const int rings = 9, segments = 14;
  for (int r = 0; r <= rings; ++r)
    for (int s = 0; s < segments; ++s) {
      const double theta = std::numbers::pi * r / rings, phi = 2 * std::numbers::pi * s / segments;
      sphere.positions.emplace_back(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                    float(std::sin(theta) * std::sin(phi)));
    }
  const auto index = [&](int r, int s) { return std::uint32_t(r * segments + (s % segments)); };
  for (int r = 0; r < rings; ++r)
    for (int s = 0; s < segments; ++s) {
      if (r > 0) sphere.triangles.push_back({index(r, s), index(r + 1, s), index(r, s + 1)});
      if (r < rings - 1) sphere.triangles.push_back({index(r, s + 1), index(r + 1, s), index(r + 1, s + 1)});
    }
  sphere.colours.assign(sphere.triangles.size(), Rgb8{255, 255, 255});

  Scene scene;
  scene.canvas = Canvas{91, 77, kBackground};
  scene.viewport = Viewport{1, 77.0 / 91.0, 1};
  const Chain chain = SceneChain(scene);
  std::mt19937 random(11);
  std::uniform_real_distribution<double> angle(-180, 180), offset(-0.3, 0.3);
  for (int round = 0; round < 3; ++round) {
    Transform t;
    t.scale = glm::dvec3(1.0);
    t.rotation = Rotation(glm::normalize(glm::dvec3(offset(random), 1, offset(random))), angle(random));
    t.translation = glm::dvec3(offset(random), offset(random), 4.2);  // wholly inside the view: no clipping
    const glm::dmat4 f = InstanceMatrix(chain, t);
    const glm::mat4 f_float(f);

    // Facing from the projected winding (every vertex is in front of the camera here).
    const auto facing = [&](std::size_t i) {
      glm::dvec2 p[3];
      for (std::size_t k = 0; k < 3; ++k) {
        const glm::dvec4 c = f * glm::dvec4(glm::dvec3(sphere.positions[sphere.triangles[i][k]]), 1.0);
        p[k] = glm::dvec2(c) / c.w;
      }
      return (p[1].x - p[0].x) * (p[2].y - p[0].y) - (p[2].x - p[0].x) * (p[1].y - p[0].y);
    };
    const Coverage front = CountCoverage(91, 77, sphere, f_float, [&](std::size_t i) { return facing(i) > 0; });
    const Coverage back = CountCoverage(91, 77, sphere, f_float, [&](std::size_t i) { return facing(i) < 0; });
    std::size_t covered = 0;
    for (std::size_t i = 0; i < front.cpu.size(); ++i) {
      INFO("round " << round << ", pixel " << i % 91 << ", " << i / 91);
      REQUIRE(front.gpu[i] == front.cpu[i]);
      REQUIRE(back.gpu[i] == back.cpu[i]);
      REQUIRE(front.cpu[i] <= 1);
      REQUIRE(back.cpu[i] <= 1);
      REQUIRE(front.cpu[i] == back.cpu[i]);
      covered += std::size_t(front.cpu[i]);
    }
    REQUIRE(covered > 1000);
  }
  test::RequireNoValidationMessages();
}
