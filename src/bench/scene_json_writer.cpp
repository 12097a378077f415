#include "bench/scene_json_writer.hpp"

#include "chain/matrices.hpp"
#include "scene/model_reader.hpp"
#include "scene/rotation.hpp"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <numbers>

namespace twinraster::bench {

void RotationAxisAngle(const glm::dmat3& r, glm::dvec3& axis, double& degrees) {
  // Rotation(a, θ) = cos θ·I − sin θ·[a]× + (1 − cos θ)·a·aᵀ (rotation.cpp): with M(row, col) =
  // r[col][row], its antisymmetric part gives 2·sin θ·a, its trace 1 + 2·cos θ.
  const glm::dvec3 twice_sine_axis(r[2][1] - r[1][2], r[0][2] - r[2][0], r[1][0] - r[0][1]);
  const double sine = glm::length(twice_sine_axis) / 2, cosine = (r[0][0] + r[1][1] + r[2][2] - 1) / 2;
  degrees = std::atan2(sine, cosine) * 180 / std::numbers::pi;
  if (sine > 1e-6) {
    axis = twice_sine_axis / (2 * sine);
    return;
  }
  if (cosine > 0) {  // no turn at all, or almost none: any axis
    axis = sine > 0 ? twice_sine_axis / (2 * sine) : glm::dvec3(0, 1, 0);
    return;
  }
  // Near a half turn: (M + Mᵀ)/2 = cos θ·I + (1 − cos θ)·a·aᵀ, so a·aᵀ's largest column gives a,
  // and the antisymmetric part, small as it is, its sign.
  glm::dmat3 outer;
  for (int c = 0; c < 3; ++c)
    for (int row = 0; row < 3; ++row)
      outer[c][row] = ((r[c][row] + r[row][c]) / 2 - (c == row ? cosine : 0.0)) / (1 - cosine);
  int largest = 0;
  for (int k = 1; k < 3; ++k)
    if (outer[k][k] > outer[largest][largest]) largest = k;
  axis = glm::normalize(outer[largest]);
  if (glm::dot(axis, twice_sine_axis) < 0) axis = -axis;
}

ObjectTransform DecomposeModelMatrix(const glm::dmat4& m) {
  ObjectTransform t;
  t.translation = glm::dvec3(m[3]);
  glm::dmat3 rotation(m);  // columns R·S: column k is R's column k times scale k
  for (int k = 0; k < 3; ++k) {
    t.scale[k] = glm::length(rotation[k]);
    if (t.scale[k] > 0) rotation[k] /= t.scale[k];
  }
  if (glm::determinant(rotation) < 0) {  // a mirror: into the z scale
    t.scale.z = -t.scale.z;
    rotation[2] = -rotation[2];
  }
  RotationAxisAngle(rotation, t.axis, t.degrees);
  Transform rebuilt;
  rebuilt.scale = t.scale;
  rebuilt.rotation = Rotation(t.axis, t.degrees);
  rebuilt.translation = t.translation;
  const glm::dmat4 back = ModelMatrix(rebuilt);
  for (int c = 0; c < 4; ++c)
    for (int row = 0; row < 4; ++row) t.residual = std::max(t.residual, std::abs(back[c][row] - m[c][row]));
  return t;
}

namespace {

class JsonText {
 public:
  std::string text;
  void Put(std::string_view s) { text += s; }
  void Number(double x) {
    char buffer[32];
    text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }
  void FloatNumber(float x) {
    char buffer[32];
    text.append(buffer, std::to_chars(buffer, buffer + sizeof buffer, x).ptr);
  }
  void Integer(std::uint64_t x) { text += std::to_string(x); }
  void Vec3(const glm::dvec3& v) {
    Put("[");
    for (int k = 0; k < 3; ++k) {
      if (k) Put(", ");
      Number(v[k]);
    }
    Put("]");
  }
  void Colour(const Rgb8& c) {
    Put("[");
    Integer(c.r);
    Put(", ");
    Integer(c.g);
    Put(", ");
    Integer(c.b);
    Put("]");
  }
  void Rotation(const glm::dmat3& r) {
    glm::dvec3 axis;
    double degrees = 0;
    RotationAxisAngle(r, axis, degrees);
    Put("{\"axis\": ");
    Vec3(axis);
    Put(", \"degrees\": ");
    Number(degrees);
    Put("}");
  }
};

void PutModel(JsonText& j, const Model& model, JsonDigits digits, bool lit) {
  j.Put("{\"vertices\": [");
  for (std::size_t i = 0; i < model.vertices.size(); ++i) {
    j.Put(i ? ",\n      [" : "\n      [");
    for (int k = 0; k < 3; ++k) {
      if (k) j.Put(", ");
      if (digits == JsonDigits::kFloat)
        j.FloatNumber(static_cast<float>(model.vertices[i][k]));
      else
        j.Number(model.vertices[i][k]);
    }
    j.Put("]");
  }
  j.Put("],\n    \"triangles\": [");
  for (std::size_t i = 0; i < model.triangles.size(); ++i) {
    const Triangle& t = model.triangles[i];
    j.Put(i ? ",\n      [" : "\n      [");
    for (const std::uint32_t v : t.v) {
      j.Integer(v);
      j.Put(", ");
    }
    j.Colour(t.colour);
    j.Put("]");
  }
  j.Put("]");
  if (lit) {
    j.Put(",\n    \"shading\": \"");
    j.Put(ShadingName(model.shading));
    j.Put("\"");
  }
  j.Put("}");
}

void PutLighting(JsonText& j, const Lighting& lighting) {
  j.Put(",\n  \"lighting\": {\"ambient\": ");
  j.Number(lighting.ambient);
  j.Put(", \"lights\": [");
  for (std::size_t i = 0; i < lighting.lights.size(); ++i) {
    const Light& light = lighting.lights[i];
    j.Put(i ? ", " : "");
    const bool directional = light.kind == Light::Kind::kDirectional;
    j.Put(directional ? "{\"type\": \"directional\", \"direction\": " : "{\"type\": \"point\", \"position\": ");
    j.Vec3(light.vector);
    j.Put(", \"intensity\": ");
    j.Number(light.intensity);
    j.Put("}");
  }
  j.Put("]}");
}

}  // namespace

std::string SceneAsJson(const Scene& scene, JsonDigits digits) {
  JsonText j;
  j.Put("{\n  \"comment\": \"written by twinraster bench --loaders from ");
  for (const char c : scene.name) {  // a file's stem, kept to what needs no escaping
    if (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') j.text += c;
  }
  j.Put("\",\n  \"canvas\": {\"width\": ");
  j.Integer(scene.canvas.width);
  j.Put(", \"height\": ");
  j.Integer(scene.canvas.height);
  j.Put(", \"background\": ");
  j.Colour(scene.canvas.background);
  j.Put("},\n  \"viewport\": {\"width\": ");
  j.Number(scene.viewport.width);
  j.Put(", \"height\": ");
  j.Number(scene.viewport.height);
  j.Put(", \"distance\": ");
  j.Number(scene.viewport.distance);
  if (scene.viewport.projection == Projection::kOrthographic) j.Put(", \"projection\": \"orthographic\"");
  j.Put("},\n  \"depth\": {\"near\": ");
  j.Number(scene.depth.near);
  j.Put(", \"far\": ");
  // A glTF camera without zfar has an infinite far plane, which JSON cannot write: the loader's
  // largest number stands for it.
  j.Number(std::isfinite(scene.depth.far) ? scene.depth.far : 1e12);
  if (scene.depth.reversed) j.Put(", \"reversed\": true");
  j.Put("},\n  \"camera\": {\"position\": ");
  j.Vec3(scene.camera.position);
  j.Put(", \"rotation\": ");
  j.Rotation(scene.camera.rotation);
  j.Put("}");
  if (scene.lighting) PutLighting(j, *scene.lighting);
  j.Put(",\n  \"models\": {");
  for (std::size_t m = 0; m < scene.models.size(); ++m) {
    j.Put(m ? ",\n  \"m" : "\n  \"m");
    j.Integer(m);
    j.Put("\": ");
    PutModel(j, scene.models[m], digits, scene.lighting.has_value());
  }
  j.Put("},\n  \"instances\": [");
  for (std::size_t i = 0; i < scene.instances.size(); ++i) {
    const Instance& instance = scene.instances[i];
    const ObjectTransform t = DecomposeModelMatrix(ModelMatrix(instance.transform));
    j.Put(i ? ",\n    {\"model\": \"m" : "\n    {\"model\": \"m");
    j.Integer(instance.model);
    j.Put("\", \"transform\": {\"scale\": ");
    j.Vec3(t.scale);
    j.Put(", \"rotation\": {\"axis\": ");
    j.Vec3(t.axis);
    j.Put(", \"degrees\": ");
    j.Number(t.degrees);
    j.Put("}, \"translation\": ");
    j.Vec3(t.translation);
    j.Put("}}");
  }
  j.Put("]\n}\n");
  return std::move(j.text);
}

}  // namespace twinraster::bench
