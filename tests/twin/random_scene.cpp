#include "random_scene.hpp"

#include <cmath>
#include <random>
#include <string>

namespace twinraster::test {

namespace {

using json = nlohmann::ordered_json;

class Dice {
 public:
  explicit Dice(std::uint32_t seed) : engine_(seed) {}
  double Uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }
  double LogUniform(double lo, double hi) { return std::exp(Uniform(std::log(lo), std::log(hi))); }
  int Int(int lo, int hi) { return std::uniform_int_distribution<int>(lo, hi)(engine_); }
  bool Chance(double p) { return Uniform(0, 1) < p; }
  json Vec3(double lo, double hi) { return json::array({Uniform(lo, hi), Uniform(lo, hi), Uniform(lo, hi)}); }
  json Colour() { return json::array({Int(0, 255), Int(0, 255), Int(0, 255)}); }

 private:
  std::mt19937 engine_;
};

json Cube(Dice& dice) {
  json triangles = json::array();
  const int faces[12][3] = {{0, 1, 2}, {0, 2, 3}, {4, 0, 3}, {4, 3, 7}, {5, 4, 7}, {5, 7, 6},
                            {1, 5, 6}, {1, 6, 2}, {4, 5, 1}, {4, 1, 0}, {2, 6, 7}, {2, 7, 3}};
  for (const auto& f : faces) triangles.push_back({f[0], f[1], f[2], dice.Colour()});
  return {{"vertices",
           {{1, 1, 1}, {-1, 1, 1}, {-1, -1, 1}, {1, -1, 1}, {1, 1, -1}, {-1, 1, -1}, {-1, -1, -1}, {1, -1, -1}}},
          {"triangles", triangles}};
}

// Random vertices, random index triples (repeated indices make zero-area triangles on purpose).
json Blob(Dice& dice, double extent) {
  json vertices = json::array(), triangles = json::array();
  const int n = dice.Int(3, 16);
  for (int i = 0; i < n; ++i) vertices.push_back(dice.Vec3(-extent, extent));
  const int t = dice.Int(1, 24);
  for (int i = 0; i < t; ++i)
    triangles.push_back({dice.Int(0, n - 1), dice.Int(0, n - 1), dice.Int(0, n - 1), dice.Colour()});
  return {{"vertices", vertices}, {"triangles", triangles}};
}

// Long thin triangles: the third vertex a hair away from the line through the first two.
json Slivers(Dice& dice) {
  json vertices = json::array(), triangles = json::array();
  const int t = dice.Int(1, 8);
  for (int i = 0; i < t; ++i) {
    const double ax = dice.Uniform(-2, 2), ay = dice.Uniform(-2, 2), az = dice.Uniform(-2, 2);
    const double bx = dice.Uniform(-2, 2), by = dice.Uniform(-2, 2), bz = dice.Uniform(-2, 2);
    const double s = dice.Uniform(0, 1), offset = dice.LogUniform(1e-6, 1e-2);
    vertices.push_back({ax, ay, az});
    vertices.push_back({bx, by, bz});
    vertices.push_back({ax + s * (bx - ax) + offset, ay + s * (by - ay) - offset, az + s * (bz - az)});
    triangles.push_back({3 * i, 3 * i + 1, 3 * i + 2, dice.Colour()});
  }
  return {{"vertices", vertices}, {"triangles", triangles}};
}

// A sub-pixel model (scaled down by its instance) or a huge one (crossing the near plane,
// reaching behind the camera and far outside the viewport).
json Sized(Dice& dice, double extent) { return Blob(dice, extent); }

json Rotation(Dice& dice) {
  if (dice.Chance(0.3)) {
    json list = json::array();
    for (const char* axis : {"z", "y", "x"}) list.push_back({{"axis", axis}, {"degrees", dice.Uniform(-180, 180)}});
    return list;
  }
  json axis = dice.Vec3(-1, 1);
  if (std::abs(double(axis[0])) + std::abs(double(axis[1])) + std::abs(double(axis[2])) < 1e-3) axis = "y";
  return {{"axis", axis}, {"degrees", dice.Uniform(-360, 360)}};
}

json Scale(Dice& dice) {
  if (dice.Chance(0.5)) return dice.LogUniform(0.1, 3) * (dice.Chance(0.1) ? -1 : 1);
  json s = json::array();
  for (int i = 0; i < 3; ++i) s.push_back(dice.LogUniform(0.1, 3) * (dice.Chance(0.1) ? -1 : 1));
  return s;
}

}  // namespace

json RandomSceneJson(std::uint32_t seed) {
  Dice dice(seed);
  json scene;
  scene["comment"] = "random scene, seed " + std::to_string(seed);
  // Mostly moderate canvases, some tiny ones; the viewport's aspect rarely matches the canvas.
  const bool tiny = dice.Chance(0.1);
  scene["canvas"] = {{"width", tiny ? dice.Int(1, 8) : dice.Int(16, 200)},
                     {"height", tiny ? dice.Int(1, 8) : dice.Int(16, 200)},
                     {"background", dice.Colour()}};
  const double vw = dice.Uniform(0.5, 2);
  scene["viewport"] = {{"width", vw}, {"height", vw * dice.Uniform(0.5, 2)}, {"distance", dice.Uniform(0.5, 2)}};
  const double near = dice.LogUniform(0.01, 1);
  // Usually far enough to hold the whole cloud; sometimes cutting through it (far-plane clipping).
  const double far = dice.Chance(0.8) ? dice.LogUniform(40, 1e4) : near * dice.LogUniform(10, 1e3);
  scene["depth"] = {{"near", near}, {"far", far}};

  scene["models"] = {{"cube", Cube(dice)},
                     {"blob", Blob(dice, 1.5)},
                     {"slivers", Slivers(dice)},
                     {"tiny", Sized(dice, 0.004)},
                     {"huge", Sized(dice, 60)}};
  const char* names[] = {"cube", "blob", "slivers", "tiny", "huge"};
  const double weights[] = {3, 3, 2, 2, 1};
  std::discrete_distribution<int> pick(std::begin(weights), std::end(weights));
  std::mt19937 picker(seed ^ 0x9e3779b9u);
  json instances = json::array();
  const int count = dice.Int(2, 10);
  for (int i = 0; i < count; ++i) {
    instances.push_back(
        {{"model", names[pick(picker)]},
         {"transform",
          {{"scale", Scale(dice)},
           {"rotation", Rotation(dice)},
           {"translation", json::array({dice.Uniform(-4, 4), dice.Uniform(-4, 4), dice.Uniform(2, 12)})}}}});
  }
  scene["instances"] = instances;

  // The cloud of instances fills [-4, 4] x [-4, 4] x [2, 12]. Cameras: inside it looking at one of
  // the instances, outside it looking at its middle, or the chapter's position + rotation.
  const double kind = dice.Uniform(0, 1);
  const json up = json::array({dice.Uniform(-0.3, 0.3), 1, dice.Uniform(-0.3, 0.3)});
  if (kind < 0.4) {
    const json& target = instances[static_cast<std::size_t>(dice.Int(0, count - 1))]["transform"]["translation"];
    scene["camera"] = {{"eye", json::array({dice.Uniform(-4, 4), dice.Uniform(-4, 4), dice.Uniform(2, 12)})},
                       {"center", target},
                       {"up", up}};
  } else if (kind < 0.8) {
    scene["camera"] = {{"eye", json::array({dice.Uniform(-15, 15), dice.Uniform(-10, 10), dice.Uniform(-12, -2)})},
                       {"center", json::array({dice.Uniform(-2, 2), dice.Uniform(-2, 2), dice.Uniform(5, 9)})},
                       {"up", up}};
  } else {
    scene["camera"] = {{"position", json::array({dice.Uniform(-2, 2), dice.Uniform(-2, 2), dice.Uniform(-6, 0)})},
                       {"rotation", json::array({json{{"axis", "x"}, {"degrees", dice.Uniform(-20, 20)}},
                                                 json{{"axis", "y"}, {"degrees", dice.Uniform(-30, 30)}}})}};
  }
  return scene;
}

}  // namespace twinraster::test
