#include "support/lit_scene.hpp"

#include "scene/rotation.hpp"

#include <glm/geometric.hpp>

#include <cmath>
#include <numbers>
#include <random>
#include <string>

namespace twinraster::test {
namespace {

class Dice {
 public:
  explicit Dice(std::uint32_t seed) : engine_(seed) {}
  double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  int Int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  bool Chance(double p) { return Uniform(0, 1) < p; }
  glm::dvec3 Vec3(double lo, double hi) { return {Uniform(lo, hi), Uniform(lo, hi), Uniform(lo, hi)}; }
  Rgb8 Colour() {
    return Rgb8{static_cast<std::uint8_t>(Int(0, 255)), static_cast<std::uint8_t>(Int(0, 255)),
                static_cast<std::uint8_t>(Int(0, 255))};
  }

 private:
  std::mt19937 engine_;
};

}  // namespace

Model LumpySphere(std::uint32_t seed, int rings, int segments, bool normals, Shading shading) {
  Dice dice(seed);
  Model model;
  model.name = "lumpy-" + std::to_string(seed);
  model.shading = shading;
  const double pi = std::numbers::pi;
  const auto index = [&](int ring, int segment) {
    return static_cast<std::uint32_t>(ring * segments + (segment % segments));
  };
  for (int ring = 0; ring < rings + 1; ++ring) {
    const double theta = pi * ring / rings;
    for (int segment = 0; segment < segments; ++segment) {
      const double phi = 2 * pi * segment / segments;
      const double r = 1 + dice.Uniform(-0.15, 0.15);
      const glm::dvec3 unit(std::sin(theta) * std::cos(phi), std::cos(theta), std::sin(theta) * std::sin(phi));
      model.vertices.push_back(r * unit);
      if (normals) model.normals.push_back(unit + dice.Vec3(-0.2, 0.2));
    }
  }
  const Rgb8 colour = dice.Colour();
  for (int ring = 0; ring < rings; ++ring) {
    for (int segment = 0; segment < segments; ++segment) {
      const std::uint32_t a = index(ring, segment), b = index(ring, segment + 1), c = index(ring + 1, segment + 1),
                          d = index(ring + 1, segment);
      const Rgb8 face = dice.Chance(0.2) ? dice.Colour() : colour;
      model.triangles.push_back(Triangle{{a, b, c}, face});
      model.triangles.push_back(Triangle{{a, c, d}, face});
      if (normals) {
        // Vertex normals shared between the faces around a vertex, but now and then a corner
        // without one (an OBJ face written without vn): the chain averages the faces there.
        const auto corner = [&](std::uint32_t v) { return dice.Chance(0.05) ? kNoNormal : v; };
        model.triangle_normals.push_back({corner(a), corner(b), corner(c)});
        model.triangle_normals.push_back({corner(a), corner(c), corner(d)});
      }
    }
  }
  return model;
}

Scene RandomLitScene(std::uint32_t seed) {
  Dice dice(seed);
  Scene scene;
  scene.name = "random-lit-" + std::to_string(seed);
  scene.canvas = Canvas{.width = static_cast<std::uint32_t>(dice.Int(16, 200)),
                        .height = static_cast<std::uint32_t>(dice.Int(16, 200)),
                        .background = dice.Colour()};
  scene.viewport =
      Viewport{.width = 1, .height = scene.canvas.height / static_cast<double>(scene.canvas.width), .distance = 1};
  scene.depth = Depth{.near = dice.Chance(0.5) ? 0.1 : 0.01, .far = 50, .reversed = dice.Chance(0.3)};
  if (dice.Chance(0.15)) scene.viewport.projection = Projection::kOrthographic;

  const int models = dice.Int(1, 3);
  for (int m = 0; m < models; ++m) {
    const int pick = dice.Int(0, 2);
    const Shading shading = pick == 0   ? Shading::kFlat
                            : pick == 1 ? Shading::kGouraud
                                        : (dice.Chance(0.5) ? Shading::kUnlit : Shading::kGouraud);
    scene.models.push_back(LumpySphere(seed * 31u + static_cast<std::uint32_t>(m), dice.Int(3, 12), dice.Int(3, 16),
                                       dice.Chance(0.5), shading));
  }
  const int instances = dice.Int(1, 6);
  for (int i = 0; i < instances; ++i) {
    Instance instance;
    instance.model = static_cast<std::size_t>(dice.Int(0, models - 1));
    glm::dvec3 scale = dice.Vec3(0.3, 2.5);
    for (int k = 0; k < 3; ++k) {
      if (dice.Chance(0.2)) scale[k] = -scale[k];  // mirrors: the normal matrix flips with them
    }
    instance.transform.scale = scale;
    instance.transform.rotation =
        Rotation(glm::normalize(dice.Vec3(-1, 1) + glm::dvec3(0, 0, 1e-3)), dice.Uniform(0, 360));
    instance.transform.translation = dice.Vec3(-3, 3) + glm::dvec3(0, 0, 6);
    scene.instances.push_back(instance);
  }
  // Most cameras look from outside; some sit inside a mesh, where the near plane cuts triangles.
  if (dice.Chance(0.25)) {
    scene.camera.position = scene.instances[0].transform.translation + dice.Vec3(-0.3, 0.3);
    scene.camera.rotation = Rotation(glm::dvec3(0, 1, 0), dice.Uniform(0, 360));
  } else {
    scene.camera.position = dice.Vec3(-1, 1);
  }

  Lighting lighting;
  lighting.ambient = dice.Chance(0.2) ? 0.0 : dice.Uniform(0, 0.4);
  const int lights = dice.Int(1, 3);
  for (int l = 0; l < lights; ++l) {
    Light light;
    light.intensity = dice.Uniform(0.1, 1.2);  // the sum may pass 1: min(I, 1) caps it
    if (dice.Chance(0.5)) {
      light.kind = Light::Kind::kDirectional;
      light.vector = dice.Vec3(-1, 1) * dice.Uniform(0.1, 10);  // any length: l is divided by |l|
    } else {
      light.kind = Light::Kind::kPoint;
      // Some inside a mesh, some between the meshes and the camera.
      light.vector = dice.Chance(0.3) ? scene.instances[0].transform.translation + dice.Vec3(-0.2, 0.2)
                                      : dice.Vec3(-4, 4) + glm::dvec3(0, 0, 3);
    }
    lighting.lights.push_back(light);
  }
  scene.lighting = lighting;
  return scene;
}

Scene RandomVertexColourScene(std::uint32_t seed) {
  Scene scene = RandomLitScene(seed);
  Dice dice(seed ^ 0x9e3779b9u);  // apart from the scene's own dice, which made its geometry
  if (seed % 3 == 0) {
    scene.lighting.reset();
    for (Model& model : scene.models) model.shading = Shading::kUnlit;
  }
  for (Model& model : scene.models) {
    model.vertex_colours.clear();
    for (std::size_t v = 0; v < model.vertices.size(); ++v) model.vertex_colours.push_back(dice.Colour());
  }
  return scene;
}

}  // namespace twinraster::test
