// The chapter's matrices against values derived by hand from its formulas.
#include "chain/matrices.hpp"

#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <cmath>

using namespace twinraster;

namespace {

constexpr double kTolerance = 1e-12;

void RequireNear(const glm::dmat4& actual, const double (&rows)[4][4]) {
  for (int r = 0; r < 4; ++r)
    for (int c = 0; c < 4; ++c) {
      INFO("row " << r << ", column " << c);
      REQUIRE(actual[c][r] == Approx(rows[r][c]).margin(kTolerance).epsilon(0));
    }
}

Scene Load(const std::string& name) { return LoadScene(test::SourcePath("scenes/" + name + ".json")); }

const double kSqrt3 = std::sqrt(3.0);

}  // namespace

TEST_CASE("The chapter demo's rotation about Y, by hand", "[matrices]") {
  // Rows [cos θ, 0, -sin θ], [0, 1, 0], [sin θ, 0, cos θ]; θ = -30°: cos = √3/2, sin = -1/2.
  RequireNear(Rotation4(Rotation({0, 1, 0}, -30)),
              {{kSqrt3 / 2, 0, 0.5, 0}, {0, 1, 0, 0}, {-0.5, 0, kSqrt3 / 2, 0}, {0, 0, 0, 1}});
  // X and Z with the same handedness: +Z toward +Y about X, +Y toward +X about Z.
  RequireNear(Rotation4(Rotation({1, 0, 0}, 90)), {{1, 0, 0, 0}, {0, 0, 1, 0}, {0, -1, 0, 0}, {0, 0, 0, 1}});
  RequireNear(Rotation4(Rotation({0, 0, 1}, 90)), {{0, 1, 0, 0}, {-1, 0, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
}

TEST_CASE("cgfs-transforms: M_Camera = C_R⁻¹ · C_T⁻¹ by hand", "[matrices]") {
  // C_R⁻¹ = C_Rᵀ = [[√3/2, 0, -1/2], [0, 1, 0], [1/2, 0, √3/2]]; translation column = C_R⁻¹ · (3, -1, -2).
  RequireNear(
      CameraMatrix(Load("cgfs-transforms").camera),
      {{kSqrt3 / 2, 0, -0.5, 3 * kSqrt3 / 2 + 1}, {0, 1, 0, -1}, {0.5, 0, kSqrt3 / 2, 1.5 - kSqrt3}, {0, 0, 0, 1}});
}

TEST_CASE("cgfs-transforms: M_Model = I_T · I_R · I_S by hand", "[matrices]") {
  const Scene scene = Load("cgfs-transforms");
  RequireNear(ModelMatrix(scene.instances[0].transform),
              {{0.75, 0, 0, -1.5}, {0, 0.75, 0, 0}, {0, 0, 0.75, 7}, {0, 0, 0, 1}});
  const double c = std::cos(195 * M_PI / 180), s = std::sin(195 * M_PI / 180);
  RequireNear(ModelMatrix(scene.instances[1].transform),
              {{c, 0, -s, 1.25}, {0, 1, 0, 2.5}, {s, 0, c, 7.5}, {0, 0, 0, 1}});
}

TEST_CASE("M_Projection from Vw, Vh, d, Cw, Ch, near, far by hand", "[matrices]") {
  // x' = 2·d/Vw · x, y' = -2·d/Vh · y, z' = f/(f-n) · z - f·n/(f-n), w' = z.
  const Viewport viewport{1.5, 0.75, 2};
  const Canvas canvas{800, 400, {}};
  const Depth depth{0.5, 40};
  RequireNear(ProjectionMatrix(viewport, canvas, depth),
              {{2 * 2 / 1.5, 0, 0, 0}, {0, -2 * 2 / 0.75, 0, 0}, {0, 0, 40 / 39.5, -40 * 0.5 / 39.5}, {0, 0, 1, 0}});
  // The chapter's own 3x4 is the first, second and fourth rows of M · P before CanvasToClip.
  const glm::dmat4 chapter = ViewportToCanvas(viewport, canvas) * PerspectiveMatrix(viewport, depth);
  REQUIRE(chapter[0][0] == Approx(2 * 800 / 1.5).epsilon(kTolerance));   // d·Cw/Vw
  REQUIRE(chapter[1][1] == Approx(2 * 400 / 0.75).epsilon(kTolerance));  // d·Ch/Vh
  REQUIRE(chapter[2][3] == 1);
}

TEST_CASE("Catlike's rotations are this project's with the angles negated", "[matrices]") {
  // Catlike Coding, Rendering 1, with θ in degrees: Rz = [[c,-s,0],[s,c,0],[0,0,1]],
  // Ry = [[c,0,s],[0,1,0],[-s,0,c]], Rx = [[1,0,0],[0,c,-s],[0,s,c]], applied z, then y, then x.
  const auto rad = [](double deg) { return deg * M_PI / 180; };
  const double cx = std::cos(rad(20)), sx = std::sin(rad(20)), cy = std::cos(rad(30)), sy = std::sin(rad(30)),
               cz = std::cos(rad(40)), sz = std::sin(rad(40));
  const glm::dmat4 rx = FromRows({{1, 0, 0, 0}, {0, cx, -sx, 0}, {0, sx, cx, 0}, {0, 0, 0, 1}});
  const glm::dmat4 ry = FromRows({{cy, 0, sy, 0}, {0, 1, 0, 0}, {-sy, 0, cy, 0}, {0, 0, 0, 1}});
  const glm::dmat4 rz = FromRows({{cz, -sz, 0, 0}, {sz, cz, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}});
  const glm::dmat4 catlike = rx * ry * rz;
  const glm::dmat4 ours = Rotation4(Load("catlike-rotations").instances[0].transform.rotation);
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) REQUIRE(ours[c][r] == Approx(catlike[c][r]).margin(kTolerance));
}

TEST_CASE("The demo camera turned -30° about Y looks toward +X", "[matrices]") {
  // The chapter demo's camera (shared/reference/chapter-scenes.md): forward is (0.5, 0, 0.866).
  const glm::dvec3 forward = Load("cgfs-transforms").camera.rotation * glm::dvec3(0, 0, 1);
  REQUIRE(forward.x == Approx(0.5).margin(kTolerance));
  REQUIRE(forward.y == Approx(0).margin(kTolerance));
  REQUIRE(forward.z == Approx(kSqrt3 / 2).margin(kTolerance));
}

TEST_CASE("lookat: eye at the origin of camera space, center straight ahead on +Z, up is +Y", "[matrices]") {
  const glm::dvec3 eye(4, 3, -6), center(0, 0, 0);
  const Camera camera = CameraLookingAt(eye, center, {0, 1, 0});
  const glm::dmat4 m = CameraMatrix(camera);
  const glm::dvec4 e = m * glm::dvec4(eye, 1), c = m * glm::dvec4(center, 1);
  REQUIRE(glm::length(glm::dvec3(e)) == Approx(0).margin(kTolerance));
  REQUIRE(c.x == Approx(0).margin(kTolerance));
  REQUIRE(c.y == Approx(0).margin(kTolerance));
  REQUIRE(c.z == Approx(glm::length(center - eye)).epsilon(kTolerance));
  // A point above the centre (world +Y) appears above it (camera +Y); world +X, seen from
  // (4, 3, -6) looking roughly along +Z, lies to the right (camera +X) in a left-handed frame.
  const glm::dvec4 above = m * glm::dvec4(0, 1, 0, 1);
  REQUIRE(above.y > 0);
  const glm::dvec4 right_of_center = m * glm::dvec4(1, 0, 0, 1);
  REQUIRE(right_of_center.x > 0);
}

TEST_CASE("Reversed Z maps near to depth 1 and far to depth 0", "[matrices]") {
  const Viewport viewport{1, 1, 1};
  const Canvas canvas{100, 100, {}};
  for (const bool reversed : {false, true}) {
    const Depth depth{0.5, 40, reversed};
    const glm::dmat4 p = ProjectionMatrix(viewport, canvas, depth);
    const auto depth_at = [&](double z) {
      const glm::dvec4 c = p * glm::dvec4(0, 0, z, 1);
      return c.z / c.w;
    };
    REQUIRE(depth_at(0.5) == Approx(reversed ? 1.0 : 0.0).margin(1e-15));
    REQUIRE(depth_at(40) == Approx(reversed ? 0.0 : 1.0).margin(1e-15));
    // Standard and reversed depths add up to 1 everywhere in between.
    const Depth other{0.5, 40, !reversed};
    const glm::dmat4 q = ProjectionMatrix(viewport, canvas, other);
    const glm::dvec4 c = q * glm::dvec4(0, 0, 7.25, 1);
    REQUIRE(depth_at(7.25) + c.z / c.w == Approx(1.0).margin(1e-15));
  }
}

TEST_CASE("The orthographic P by hand: x and y kept, depth linear from near to far, w = 1",
          "[matrices][orthographic]") {
  // near 2, far 10: depth = (z - 2) / 8 = z/8 - 1/4; reversed: (10 - z) / 8 = -z/8 + 5/4.
  RequireNear(OrthographicMatrix(Depth{2, 10, false}),
              {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0.125, -0.25}, {0, 0, 0, 1}});
  RequireNear(OrthographicMatrix(Depth{2, 10, true}), {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -0.125, 1.25}, {0, 0, 0, 1}});
  // M_Projection for a 320 x 240 canvas and an 8 x 6 viewport: x · 320/8 = 40 px per unit, then
  // 2/320 to clip: clip x = x / 4; y likewise with Vulkan's flip: clip y = -y / 3. d plays no part.
  const Viewport viewport{8, 6, 123.0, Projection::kOrthographic};
  const Canvas canvas{320, 240, {255, 255, 255}};
  const glm::dmat4 projection = ProjectionMatrix(viewport, canvas, Depth{2, 10, false});
  RequireNear(projection, {{0.25, 0, 0, 0}, {0, -1.0 / 3, 0, 0}, {0, 0, 0.125, -0.25}, {0, 0, 0, 1}});
  // A point at the near plane has depth 0 and one at the far plane depth 1, wherever x and y are.
  for (const double z : {2.0, 10.0}) {
    const glm::dvec4 clip = projection * glm::dvec4(3, -2, z, 1);
    REQUIRE(clip.w == 1.0);
    REQUIRE(clip.z == Approx(z == 2.0 ? 0.0 : 1.0).margin(kTolerance));
    REQUIRE(clip.x == 0.75);
  }
}

TEST_CASE("catlike-orthographic: the scene says orthographic, and its M_Projection has no w = z row",
          "[matrices][orthographic]") {
  const Scene scene = Load("catlike-orthographic");
  REQUIRE(scene.viewport.projection == Projection::kOrthographic);
  const glm::dmat4 projection = SceneChain(scene).projection;
  REQUIRE(projection[2][3] == 0.0);  // row 3, column 2: w does not depend on z
  REQUIRE(projection[3][3] == 1.0);
}
