// The demo's matrix arithmetic: its summation order, its rotation entries, and its matrices for
// figure 10-10 by hand.
#include "book/book_chain.hpp"

#include "scene/rotation.hpp"
#include "support/catch.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <memory>
#include <numbers>

using namespace twinraster;
using namespace twinraster::book;

namespace {

// The demo's own expression for an angle's cosine and sine, Math.cos(degrees*Math.PI/180.0), by
// glibc (BookRotation's are the project's own: these tests hold them to glibc's on these angles).
double DemoCos(double degrees) { return std::cos(degrees * std::numbers::pi / 180.0); }
double DemoSin(double degrees) { return std::sin(degrees * std::numbers::pi / 180.0); }

}  // namespace

TEST_CASE("MultiplyMM4 and MultiplyMV add left to right from 0, rounding every step", "[book][chain]") {
  // Row (1e16, 1, -1e16, 1) against ones: exactly 2, but left to right 1e16 + 1 rounds back to
  // 1e16 (the doubles there are 2 apart), then - 1e16 gives 0, then + 1 gives 1.
  Mat4x4 a{};
  a[0] = {1e16, 1, -1e16, 1};
  Mat4x4 ones{};
  for (auto& row : ones) row = {1, 1, 1, 1};
  REQUIRE(MultiplyMM4(a, ones)[0][2] == 1.0);
  REQUIRE(MultiplyMV(a, {1, 1, 1, 1})[0] == 1.0);
  // The sum starts at +0, so products that are all -0 sum to +0 (a sum started at its first
  // product would keep -0).
  Mat4x4 negative = Identity4x4();
  negative[0][0] = -1;
  REQUIRE_FALSE(std::signbit(MultiplyMV(negative, {0, 0, 0, 0})[0]));
  REQUIRE_FALSE(std::signbit(MultiplyMM4(negative, Mat4x4{})[0][0]));
}

TEST_CASE("Transposed swaps rows and columns, and the translation and scaling matrices are the demo's",
          "[book][chain]") {
  const Mat4x4 t = MakeTranslationMatrix({1.25, 2.5, 7.5});
  REQUIRE(t[0][3] == 1.25);
  REQUIRE(t[1][3] == 2.5);
  REQUIRE(t[2][3] == 7.5);
  REQUIRE(t[3] == std::array<double, 4>{0, 0, 0, 1});
  const Mat4x4 tt = Transposed(t);
  REQUIRE(tt[3] == std::array<double, 4>{1.25, 2.5, 7.5, 1});
  REQUIRE(tt[0][3] == 0);
  const Mat4x4 s = MakeScalingMatrix({0.75, 2, 3});
  REQUIRE(s[0][0] == 0.75);
  REQUIRE(s[1][1] == 2);
  REQUIRE(s[2][2] == 3);
  REQUIRE(s[3][3] == 1);
  REQUIRE(s[0][1] == 0);
}

TEST_CASE("The orientation about Y has the demo's entries: its cos and sin of degrees*pi/180, and an exact 1",
          "[book][chain]") {
  for (double degrees : {195.0, -30.0}) {
    INFO(degrees);
    const Mat4x4 m = MakeOrientationMatrix(BookRotation({0, 1, 0}, degrees));
    // MakeOYRotationMatrix's rows: [cos, 0, -sin, 0] [0, 1, 0, 0] [sin, 0, cos, 0] [0, 0, 0, 1].
    const double c = DemoCos(degrees), s = DemoSin(degrees);
    REQUIRE(m[0] == std::array<double, 4>{c, 0, -s, 0});
    REQUIRE(m[1] == std::array<double, 4>{0, 1, 0, 0});
    REQUIRE(m[2] == std::array<double, 4>{s, 0, c, 0});
    REQUIRE(m[3] == std::array<double, 4>{0, 0, 0, 1});
  }
}

TEST_CASE("Where the loader's rotation rounds its axis entry below 1, the orientation still has the demo's 1",
          "[book][chain]") {
  // Rodrigues' form gives cos θ + (1 - cos θ) on the axis; at -269° (cos = -0.01745...) the
  // subtraction rounds and the sum is 1 - 2^-53.
  const glm::dmat3 loaded = BookRotation({0, 1, 0}, -269);
  REQUIRE(loaded[1][1] == 0x1.fffffffffffffp-1);
  const Mat4x4 m = MakeOrientationMatrix(loaded);
  REQUIRE(m[1][1] == 1.0);
  REQUIRE(m[0] == std::array<double, 4>{DemoCos(-269), 0, -DemoSin(-269), 0});
  REQUIRE(m[2] == std::array<double, 4>{DemoSin(-269), 0, DemoCos(-269), 0});
  // About a tilted axis no axis is fixed: every entry is the scene's.
  const glm::dmat3 tilted = Rotation(glm::normalize(glm::dvec3{1, 1, 0}), 40);
  const Mat4x4 t = MakeOrientationMatrix(tilted);
  for (glm::length_t r = 0; r < 3; ++r)
    for (glm::length_t c = 0; c < 3; ++c) REQUIRE(t[std::size_t(r)][std::size_t(c)] == tilted[c][r]);
}

TEST_CASE("Figure 10-10's camera matrix: Transposed(R(-30°)) · T(3, -1, -2), summed as the demo sums",
          "[book][chain]") {
  Camera camera;
  camera.position = {-3, 1, 2};
  camera.rotation = Rotation({0, 1, 0}, -30);  // sin -30° = -0.5 exactly: not the demo's
  camera.book_rotation = std::make_shared<const glm::dmat3>(BookRotation({0, 1, 0}, -30));
  const Mat4x4 m = MakeCameraMatrix(camera);
  const double c = DemoCos(-30), s = DemoSin(-30);  // √3/2 and -1/2 (as 0.8660254037844387, -0.49999999999999994)
  // Transposed rows: [c, 0, s, 0] [0, 1, 0, 0] [-s, 0, c, 0]; T(-position) has column (3, -1, -2, 1).
  REQUIRE(m[0] == std::array<double, 4>{c, 0, s, ((c * 3 + 0 * -1.0) + s * -2) + 0.0});
  REQUIRE(m[1] == std::array<double, 4>{0, 1, 0, -1});
  REQUIRE(m[2] == std::array<double, 4>{-s, 0, c, ((-s * 3 + 0 * -1.0) + c * -2) + 0.0});
  REQUIRE(m[3] == std::array<double, 4>{0, 0, 0, 1});
  // By hand: 3√3/2 + 1 = 3.598076211353316 and 3/2 - √3 = -0.2320508075688772.
  REQUIRE(m[0][3] == Approx(3.598076211353316).epsilon(1e-15));
  REQUIRE(m[2][3] == Approx(-0.2320508075688772).epsilon(1e-14));
}

TEST_CASE("Figure 10-10's instance transforms: T · (R · S)", "[book][chain]") {
  Transform small;
  small.scale = {0.75, 0.75, 0.75};
  small.translation = {-1.5, 0, 7};
  const Mat4x4 a = MakeInstanceTransform(small);
  REQUIRE(a[0] == std::array<double, 4>{0.75, 0, 0, -1.5});
  REQUIRE(a[1] == std::array<double, 4>{0, 0.75, 0, 0});
  REQUIRE(a[2] == std::array<double, 4>{0, 0, 0.75, 7});
  REQUIRE(a[3] == std::array<double, 4>{0, 0, 0, 1});

  Transform turned;
  turned.rotation = Rotation({0, 1, 0}, 195);
  turned.book_rotation = std::make_shared<const glm::dmat3>(BookRotation({0, 1, 0}, 195));
  turned.translation = {1.25, 2.5, 7.5};
  const Mat4x4 b = MakeInstanceTransform(turned);
  const double c = DemoCos(195), s = DemoSin(195);
  REQUIRE(b[0] == std::array<double, 4>{c, 0, -s, 1.25});
  REQUIRE(b[1] == std::array<double, 4>{0, 1, 0, 2.5});
  REQUIRE(b[2] == std::array<double, 4>{s, 0, c, 7.5});
}

TEST_CASE("Translation only, camera at the origin: the vertex is raster-06/07's model vertex + position, bit for bit",
          "[book][chain]") {
  // Every product is by 0 or 1, hence exact, and adding a zero changes nothing: the matrices
  // reproduce the demos that have none.
  const Camera camera;
  for (const glm::dvec3 t : {glm::dvec3{-1.5, 0, 7}, glm::dvec3{1.25, 2, 7.5}, glm::dvec3{0.1, -1e-300, 1e16}}) {
    Transform transform;
    transform.translation = t;
    const Mat4x4 m = MultiplyMM4(MakeCameraMatrix(camera), MakeInstanceTransform(transform));
    for (const glm::dvec3 v : {glm::dvec3{1, -1, 1}, glm::dvec3{0.2, 0.7, -3}, glm::dvec3{-0.0, 3e-17, 1}}) {
      const Vertex4 out = MultiplyMV(m, {v.x, v.y, v.z, 1});
      REQUIRE(out == Vertex4{v.x + t.x, v.y + t.y, v.z + t.z, 1});
    }
  }
}
