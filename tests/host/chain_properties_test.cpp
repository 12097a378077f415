// Properties of the chain that hold for every shipped scene: inverses, orthonormal rotations,
// and F · V agreeing with the chapter's step-by-step route (Listing 10-3).
#include "matrices.hpp"
#include "scene_loader.hpp"
#include "support/test_support.hpp"
#include "vertex_trace.hpp"

#include <catch2/catch.hpp>

#include <glm/matrix.hpp>

#include <random>

using namespace twinraster;

namespace {

void RequireIdentity(const glm::dmat4& m, double tolerance) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) REQUIRE(m[c][r] == Approx(c == r ? 1.0 : 0.0).margin(tolerance));
}

void RequireOrthonormal(const glm::dmat3& r) {
  const glm::dmat3 product = glm::transpose(r) * r;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) REQUIRE(product[c][k] == Approx(c == k ? 1.0 : 0.0).margin(1e-12));
  REQUIRE(glm::determinant(r) == Approx(1.0).margin(1e-12));  // a rotation, not a mirror
}

}  // namespace

TEST_CASE("M_Camera times the camera's own transform C_T · C_R is the identity", "[chain]") {
  for (const auto& file : test::ShippedScenes()) {
    INFO(file.string());
    const Camera camera = LoadScene(file).camera;
    RequireIdentity(CameraMatrix(camera) * Translation(camera.position) * Rotation4(camera.rotation), 1e-12);
  }
}

TEST_CASE("Rotations are orthonormal: random axes and angles, and every shipped scene's", "[chain]") {
  std::mt19937 random(20261122);
  std::uniform_real_distribution<double> unit(-1, 1), degrees(-720, 720);
  for (int i = 0; i < 1000; ++i) {
    glm::dvec3 axis(unit(random), unit(random), unit(random));
    if (glm::length(axis) < 1e-3) continue;
    RequireOrthonormal(Rotation(glm::normalize(axis), degrees(random)));
  }
  for (const auto& file : test::ShippedScenes()) {
    INFO(file.string());
    const Scene scene = LoadScene(file);
    RequireOrthonormal(scene.camera.rotation);
    for (const Instance& instance : scene.instances) RequireOrthonormal(instance.transform.rotation);
  }
}

TEST_CASE("F · V equals Listing 10-3's step-by-step chain for every vertex of every shipped scene", "[chain]") {
  for (const auto& file : test::ShippedScenes()) {
    const Scene scene = LoadScene(file);
    const Chain chain = SceneChain(scene);
    for (std::size_t i = 0; i < scene.instances.size(); ++i) {
      const Instance& instance = scene.instances[i];
      const glm::dmat4 f = InstanceMatrix(chain, instance.transform);
      for (const glm::dvec3& v : scene.models[instance.model].vertices) {
        INFO(file.string() << " instance " << i << " vertex (" << v.x << ", " << v.y << ", " << v.z << ")");
        const glm::dvec3 camera_space = ApplyCamera(ApplyTransform(v, instance.transform), scene.camera);
        const glm::dvec4 clip = f * glm::dvec4(v, 1.0);
        // w is camera-space z, exactly the chapter's divisor.
        REQUIRE(clip.w == Approx(camera_space.z).margin(1e-12));
        if (camera_space.z == 0) continue;  // the chapter's formula has no canvas point there
        const glm::dvec2 canvas = ProjectVertex(camera_space, scene.viewport, scene.canvas);
        const double to_canvas_x = scene.canvas.width / 2.0, to_canvas_y = -(scene.canvas.height / 2.0);
        const double scale = 1 + std::abs(canvas.x) + std::abs(canvas.y);
        REQUIRE(clip.x / clip.w * to_canvas_x == Approx(canvas.x).margin(1e-12 * scale));
        REQUIRE(clip.y / clip.w * to_canvas_y == Approx(canvas.y).margin(1e-12 * scale));
      }
    }
  }
}
