// Properties of the chain that hold for every shipped scene: inverses, orthonormal rotations,
// and F · V agreeing with the chapter's step-by-step route (Listing 10-3).
#include "chain/matrices.hpp"
#include "chain/vertex_trace.hpp"
#include "scene/scene_loader.hpp"
#include "support/catch.hpp"
#include "support/test_support.hpp"

#include <glm/matrix.hpp>

#include <random>

using namespace twinraster;

namespace {

void RequireIdentity(const glm::dmat4& m, double tolerance) {
  for (int c = 0; c < 4; ++c)
    for (int r = 0; r < 4; ++r) REQUIRE(m[c][r] == Approx(c == r ? 1.0 : 0.0).margin(tolerance));
}

void RequireOrthonormal(const glm::dmat3& r, double tolerance = 1e-12) {
  const glm::dmat3 product = glm::transpose(r) * r;
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 3; ++k) REQUIRE(product[c][k] == Approx(c == k ? 1.0 : 0.0).margin(tolerance));
  REQUIRE(glm::determinant(r) == Approx(1.0).margin(tolerance));  // a rotation, not a mirror
}

// scenes/hard/accumulated-rotation.json multiplies a million small rotations without ever
// re-orthonormalizing, on purpose: its camera drifts 7.3e-11 away from orthonormal (measured), so
// properties that rely on Rᵀ = R⁻¹ hold only to that. Every other scene holds them to 1e-12.
double CameraTolerance(const std::filesystem::path& file) {
  return file.filename() == "accumulated-rotation.json" ? 1e-10 : 1e-12;
}

}  // namespace

TEST_CASE("M_Camera times the camera's own transform C_T · C_R is the identity", "[chain]") {
  for (const auto& file : test::ShippedScenes()) {
    INFO(file.string());
    const Camera camera = LoadScene(file).camera;
    RequireIdentity(CameraMatrix(camera) * Translation(camera.position) * Rotation4(camera.rotation),
                    CameraTolerance(file));
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
    RequireOrthonormal(scene.camera.rotation, CameraTolerance(file));
    for (const Instance& instance : scene.instances) RequireOrthonormal(instance.transform.rotation);
  }
}

TEST_CASE("A million accumulated steps drift from orthonormal unless re-orthonormalized", "[chain]") {
  const auto drift = [](const std::string& name) {
    const glm::dmat3 r = LoadScene(test::SourcePath("scenes/hard/" + name)).camera.rotation;
    const glm::dmat3 product = glm::transpose(r) * r;
    double worst = 0;
    for (int c = 0; c < 3; ++c)
      for (int k = 0; k < 3; ++k) worst = std::max(worst, std::abs(product[c][k] - (c == k ? 1.0 : 0.0)));
    return worst;
  };
  const double raw = drift("accumulated-rotation.json");
  const double fixed = drift("accumulated-rotation-reorthonormalized.json");
  REQUIRE(raw > 1e-12);  // the drift is real
  REQUIRE(raw < 1e-10);  // but in double it stays tiny: about 7e-11 after 1e6 steps
  REQUIRE(fixed < 1e-15);
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
        const glm::dvec2 canvas = ProjectVertex(camera_space, scene.viewport, scene.canvas);
        const double to_canvas_x = scene.canvas.width / 2.0, to_canvas_y = -(scene.canvas.height / 2.0);
        if (scene.viewport.projection == Projection::kOrthographic) {
          // w = 1: nothing is divided, and the canvas point is (x·Cw/Vw, y·Ch/Vh) to 1e-9 px.
          REQUIRE(clip.w == 1.0);
          REQUIRE(std::abs(clip.x * to_canvas_x - canvas.x) <= 1e-9);
          REQUIRE(std::abs(clip.y * to_canvas_y - canvas.y) <= 1e-9);
          continue;
        }
        // w is camera-space z, exactly the chapter's divisor.
        REQUIRE(clip.w == Approx(camera_space.z).margin(1e-12));
        if (camera_space.z == 0) continue;  // the chapter's formula has no canvas point there
        const double scale = 1 + std::abs(canvas.x) + std::abs(canvas.y);
        REQUIRE(clip.x / clip.w * to_canvas_x == Approx(canvas.x).margin(1e-12 * scale));
        REQUIRE(clip.y / clip.w * to_canvas_y == Approx(canvas.y).margin(1e-12 * scale));
      }
    }
  }
}
