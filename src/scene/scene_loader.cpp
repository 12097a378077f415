#include "scene/scene_loader.hpp"

#include "scene/json_document.hpp"
#include "scene/json_reader.hpp"
#include "scene/json_value.hpp"
#include "scene/lighting_reader.hpp"
#include "scene/model_reader.hpp"
#include "scene/rotation.hpp"

#include <glm/geometric.hpp>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>

namespace twinraster {

namespace {

constexpr std::string_view kUtf8ByteOrderMark = "\xEF\xBB\xBF";

glm::dvec3 ReadAxis(const JsonReader& r) {
  if (r.IsString()) {
    const std::string name = r.LowercaseString();  // "Y" as the chapter's text writes it
    if (name == "x") return {1, 0, 0};
    if (name == "y") return {0, 1, 0};
    if (name == "z") return {0, 0, 1};
    r.Fail("unknown axis \"" + r.String() + "\"; use \"x\", \"y\", \"z\" (in any case) or a vector [x, y, z]");
  }
  const glm::dvec3 axis = r.Vec3();
  const double length = glm::length(axis);
  if (!(length > 1e-12)) r.Fail("rotation axis must not be the zero vector");
  return axis / length;
}

// One {axis, degrees}, or a list of them applied in order (the first is applied first, so the
// matrix is the product with the first rotation on the right).
glm::dmat3 ReadRotation(const JsonReader& r) {
  if (r.IsArray()) {
    glm::dmat3 rotation(1.0);
    const std::size_t n = r.ExpectArray();
    for (std::size_t i = 0; i < n; ++i) rotation = ReadRotation(r[i]) * rotation;
    return rotation;
  }
  if (!r.IsObject()) {
    r.Fail("expected {\"axis\": ..., \"degrees\": ...} or a list of them, found " + r.TypeName());
  }
  r.ExpectObject({"axis", "degrees", "steps", "reorthonormalize"});
  const glm::dvec3 axis = ReadAxis(r.Required("axis"));
  const double degrees = r.Required("degrees").Number();
  const std::optional<JsonReader> steps = r.Find("steps");
  const std::optional<JsonReader> reorthonormalize = r.Find("reorthonormalize");
  if (!steps) {
    if (reorthonormalize) reorthonormalize->Fail("only meaningful together with \"steps\"");
    return Rotation(axis, degrees);
  }
  return AccumulatedRotation(axis, degrees, static_cast<int>(steps->Integer(1, 10'000'000)),
                             reorthonormalize && reorthonormalize->Boolean());
}

// The demos' own entries for a rotation written as one {axis, degrees}, for --rules book; null for
// a list or steps, which the demos have no counterpart for. After ReadRotation has checked it.
std::shared_ptr<const glm::dmat3> ReadBookRotation(const JsonReader& r) {
  if (!r.IsObject() || r.Find("steps")) return nullptr;
  return std::make_shared<const glm::dmat3>(BookRotation(ReadAxis(r.Required("axis")), r.Required("degrees").Number()));
}

glm::dvec3 ReadScale(const JsonReader& r) {
  if (r.IsNumber()) {
    const double s = r.Number();
    return {s, s, s};
  }
  if (!r.IsArray()) r.Fail("expected a number or [sx, sy, sz], found " + r.TypeName());
  return r.Vec3();
}

Canvas ReadCanvas(const JsonReader& r) {
  r.ExpectObject({"width", "height", "background"});
  Canvas canvas;
  canvas.width = static_cast<std::uint32_t>(r.Required("width").Integer(1, kMaxCanvasSize));
  canvas.height = static_cast<std::uint32_t>(r.Required("height").Integer(1, kMaxCanvasSize));
  if (auto background = r.Find("background")) canvas.background = ReadColour(*background);
  return canvas;
}

Viewport ReadViewport(const JsonReader& r) {
  r.ExpectObject({"width", "height", "distance", "projection"});
  Viewport viewport{r.Required("width").Positive(), r.Required("height").Positive(), r.Required("distance").Positive()};
  if (auto projection = r.Find("projection")) {
    const std::string kind = projection->String();
    if (kind == "orthographic") {
      viewport.projection = Projection::kOrthographic;
    } else if (kind != "perspective") {
      const std::string suggestion = ClosestMatch(kind, {"perspective", "orthographic"});
      projection->Fail("expected \"perspective\" or \"orthographic\", found \"" + kind + "\"" +
                       (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)"));
    }
  }
  return viewport;
}

Depth ReadDepth(const JsonReader& r) {
  r.ExpectObject({"near", "far", "reversed"});
  Depth depth;
  if (auto near = r.Find("near")) depth.near = near->Positive();
  if (auto far = r.Find("far")) depth.far = far->Number();
  if (auto reversed = r.Find("reversed")) depth.reversed = reversed->Boolean();
  if (!(depth.far > depth.near)) {
    std::ostringstream s;
    s << "far (" << depth.far << ") must be greater than near (" << depth.near << ")";
    r.Fail(s.str());
  }
  return depth;
}

Camera ReadCamera(const JsonReader& r) {
  r.ExpectObject({"position", "rotation", "eye", "center", "up"});
  const bool chapter_style = r.Find("position") || r.Find("rotation");
  const bool lookat_style = r.Find("eye") || r.Find("center") || r.Find("up");
  if (chapter_style && lookat_style) {
    r.Fail("use either position + rotation (the chapter) or eye + center + up (lookat), not both");
  }
  if (!lookat_style) {
    Camera camera;
    camera.position = r.Required("position").Vec3();
    if (auto rotation = r.Find("rotation")) {
      camera.rotation = ReadRotation(*rotation);
      camera.book_rotation = ReadBookRotation(*rotation);
    }
    return camera;
  }
  const glm::dvec3 eye = r.Required("eye").Vec3();
  const JsonReader center_reader = r.Required("center");
  const glm::dvec3 center = center_reader.Vec3();
  glm::dvec3 up(0, 1, 0);
  std::optional<JsonReader> up_reader = r.Find("up");
  if (up_reader) up = up_reader->Vec3();
  const glm::dvec3 view = center - eye;
  if (glm::length(view) == 0) center_reader.Fail("center equals eye: the camera has no view direction");
  // Closer than this (relative to where they are), the direction is mostly rounding noise.
  if (glm::length(view) < 1e-9 * std::max(1.0, glm::length(eye))) {
    center_reader.Fail("center is too close to eye (under 1e-9) to give a view direction");
  }
  if (glm::length(up) == 0) up_reader->Fail("up must not be the zero vector");
  // Parallel when the sine of the angle between up and the view direction vanishes. The bound is
  // tiny on purpose: 1e-7 away from parallel is a legitimate (hard) case, exact parallel is not.
  const double sine = glm::length(glm::cross(glm::normalize(up), glm::normalize(view)));
  if (sine < 1e-12) {
    (up_reader ? *up_reader : r).Fail("up is parallel to the view direction (center - eye)");
  }
  return CameraLookingAt(eye, center, up);
}

// Model names to indices, looked up once per instance.
using ModelIndex = std::map<std::string, std::size_t, std::less<>>;

// A lit model's normals go to world space by the normal matrix, the inverse transpose of M_Model's
// upper 3x3, which exists unless some scale factor is 0 (rotations and translations never make
// M_Model singular). `scale` is where the factors were written.
void ExpectNonZeroScale(const JsonReader& scale, const glm::dvec3& factors, const Model& model) {
  for (glm::length_t k = 0; k < 3; ++k) {
    if (factors[k] != 0) continue;
    const std::string problem = "a lit model (\"" + model.name + "\", " + ShadingName(model.shading) +
                                " shading) cannot be scaled by 0: the normal matrix, the inverse transpose of M_Model, "
                                "does not exist for a zero scale (use a non-zero scale, or \"shading\": \"unlit\")";
    if (scale.IsArray()) scale[static_cast<std::size_t>(k)].Fail(problem);
    scale.Fail(problem);
  }
}

// "transform": [{"rotation": ...}, {"translation": [...]}, {"scale": ...}]: steps applied in the
// order written, each an object with exactly one of the three keys. `lit_model`: the instance's
// model if it is lit, whose scales must not be 0.
std::shared_ptr<const std::vector<TransformStep>> ReadTransformSteps(const JsonReader& list, const Model* lit_model) {
  auto steps = std::make_shared<std::vector<TransformStep>>();
  list.ForEachElement([&](const JsonReader& r) {
    r.ExpectObject({"scale", "rotation", "translation"});
    const std::vector<std::string_view> keys = r.Keys();
    if (keys.size() != 1) {
      r.Fail("a step of a transform list needs exactly one of \"scale\", \"rotation\" or \"translation\" (found " +
             std::to_string(keys.size()) + " keys); write one step per object");
    }
    TransformStep step;
    if (auto scale = r.Find("scale")) {
      step.kind = TransformStep::Kind::kScale;
      step.vector = ReadScale(*scale);
      if (lit_model) ExpectNonZeroScale(*scale, step.vector, *lit_model);
    } else if (auto rotation = r.Find("rotation")) {
      step.kind = TransformStep::Kind::kRotation;
      step.rotation = ReadRotation(*rotation);
    } else {
      step.kind = TransformStep::Kind::kTranslation;
      step.vector = r.Required("translation").Vec3();
    }
    steps->push_back(step);
  });
  return steps;
}

// `lit_scene`: the scene has "lighting".
Instance ReadInstance(const JsonReader& r, const std::vector<Model>& models, const ModelIndex& index, bool lit_scene) {
  r.ExpectObject({"model", "transform", "grid"});
  Instance instance;
  const JsonReader model = r.Required("model");
  const std::string name = model.String();
  const auto found = index.find(name);
  if (found == index.end()) {
    std::vector<std::string> names;
    for (const Model& m : models) names.push_back(m.name);
    const std::string suggestion = ClosestMatch(name, names);
    model.Fail("no model named \"" + name + "\"" +
               (suggestion.empty() ? "" : " (did you mean \"" + suggestion + "\"?)"));
  }
  instance.model = found->second;
  const Model* lit_model =
      lit_scene && models[instance.model].shading != Shading::kUnlit ? &models[instance.model] : nullptr;
  if (auto transform = r.Find("transform")) {
    if (transform->IsArray()) {
      instance.transform.steps = ReadTransformSteps(*transform, lit_model);
      return instance;
    }
    if (!transform->IsObject()) {
      transform->Fail("expected an object (scale, rotation, translation) or a list of steps, found " +
                      transform->TypeName());
    }
    transform->ExpectObject({"scale", "rotation", "translation"});
    if (auto scale = transform->Find("scale")) {
      instance.transform.scale = ReadScale(*scale);
      if (lit_model) ExpectNonZeroScale(*scale, instance.transform.scale, *lit_model);
    }
    if (auto rotation = transform->Find("rotation")) {
      instance.transform.rotation = ReadRotation(*rotation);
      instance.transform.book_rotation = ReadBookRotation(*rotation);
    }
    if (auto translation = transform->Find("translation")) instance.transform.translation = translation->Vec3();
  }
  return instance;
}

// "grid": {"count": [nx, ny, nz], "spacing": [sx, sy, sz]}; `room` is how many more instances the
// scene may still have.
InstanceGrid ReadGrid(const JsonReader& r, std::size_t room) {
  r.ExpectObject({"count", "spacing"});
  InstanceGrid grid;
  const JsonReader count = r.Required("count");
  count.ExpectArray(3);
  for (std::size_t axis = 0; axis < 3; ++axis) {
    grid.count[axis] = static_cast<std::uint32_t>(count[axis].Integer(1, static_cast<std::int64_t>(kMaxInstances)));
  }
  if (grid.copies() > room) {
    count.Fail("the scene would have more than " + std::to_string(kMaxInstances) + " instances (this grid alone is " +
               std::to_string(grid.copies()) + ")");
  }
  grid.spacing = r.Required("spacing").Vec3();
  return grid;
}

// The grid's copies of `instance`, appended in i-fastest order.
void AppendGridCopies(const Instance& instance, const InstanceGrid& grid, std::vector<Instance>& out) {
  const auto offset = [&](std::size_t axis, std::uint32_t n) {
    return (static_cast<double>(n) - (static_cast<double>(grid.count[axis]) - 1.0) / 2.0) *
           grid.spacing[static_cast<glm::length_t>(axis)];
  };
  for (std::uint32_t k = 0; k < grid.count[2]; ++k) {
    for (std::uint32_t j = 0; j < grid.count[1]; ++j) {
      for (std::uint32_t i = 0; i < grid.count[0]; ++i) {
        Instance copy = instance;
        copy.transform.translation += glm::dvec3(offset(0, i), offset(1, j), offset(2, k));
        out.push_back(copy);
      }
    }
  }
}

// `directory`: where the paths of OBJ files start.
Scene ReadScene(const JsonText& text, const std::string& file_name, const std::filesystem::path& directory) {
  // A UTF-8 byte-order mark, as Notepad saves it, is skipped: simdjson refuses it with a message
  // that names no place. Lines and columns are then counted as an editor shows them, without it.
  std::string_view view = text.view();
  if (view.starts_with(kUtf8ByteOrderMark)) view.remove_prefix(kUtf8ByteOrderMark.size());
  RejectBinaryText(view, file_name);
  const ParsedJson document = ParseJson(view, file_name, JsonStrictness::kScene);

  const JsonReader root(document.root(), file_name);
  root.ExpectObject(
      {"comment", "canvas", "viewport", "depth", "camera", "models", "instances", "wireframe", "lighting"});
  if (auto comment = root.Find("comment")) comment->String();

  Scene scene;
  scene.name = std::filesystem::path(file_name).stem().string();
  scene.canvas = ReadCanvas(root.Required("canvas"));
  scene.viewport = ReadViewport(root.Required("viewport"));
  if (auto depth = root.Find("depth")) scene.depth = ReadDepth(*depth);
  if (auto wireframe = root.Find("wireframe")) scene.wireframe = wireframe->Boolean();
  scene.camera = ReadCamera(root.Required("camera"));
  // Before the models: whether the scene is lit decides their shading.
  if (auto lighting = root.Find("lighting")) scene.lighting = ReadLighting(*lighting);
  const bool lit = scene.lighting.has_value();

  const JsonReader models = root.Required("models");
  ModelIndex index;
  for (const std::string_view name : models.Keys()) {
    index.emplace(std::string(name), scene.models.size());
    scene.models.push_back(ReadModel(*models.Find(name), std::string(name), directory, lit));
  }

  const JsonReader instances = root.Required("instances");
  const std::size_t written = instances.ExpectArray();
  if (written > kMaxInstances) {
    instances.Fail("more than " + std::to_string(kMaxInstances) + " instances (" + std::to_string(written) + ")");
  }
  scene.instances.reserve(written);
  std::size_t at = 0;
  instances.ForEachElement([&](const JsonReader& r) {
    const Instance instance = ReadInstance(r, scene.models, index, lit);
    if (auto grid_reader = r.Find("grid")) {
      // Room for this grid, and one instance for each written instance still to come.
      const std::size_t later = written - at - 1;
      const std::size_t used = scene.instances.size() + later;
      InstanceGrid grid = ReadGrid(*grid_reader, used < kMaxInstances ? kMaxInstances - used : 0);
      grid.written = at;
      grid.first = scene.instances.size();
      const std::size_t needed = scene.instances.size() + grid.copies() + later;
      if (needed > scene.instances.capacity())
        scene.instances.reserve(std::max(needed, 2 * scene.instances.capacity()));
      AppendGridCopies(instance, grid, scene.instances);
      scene.grids.push_back(grid);
    } else {
      scene.instances.push_back(instance);
    }
    ++at;
  });
  return scene;
}

}  // namespace

Scene ParseScene(std::string_view json_text, const std::string& file_name, const std::filesystem::path& directory) {
  return ReadScene(JsonText(json_text), file_name, directory);
}

Scene LoadScene(const std::filesystem::path& file) {
  std::error_code ec;
  if (std::filesystem::is_directory(file, ec))
    throw SceneError(file.string(), "(file)", "is a directory, not a scene file");
  if (!std::filesystem::exists(file, ec)) throw SceneError(file.string(), "(file)", "no such file");
  if (!std::filesystem::is_regular_file(file, ec)) throw SceneError(file.string(), "(file)", "not a regular file");
  // Far beyond any scene a person writes; refusing it keeps /dev/zero-like inputs from eating memory.
  constexpr std::uintmax_t kMaxSceneBytes = 256u << 20;
  if (std::filesystem::file_size(file, ec) > kMaxSceneBytes) {
    throw SceneError(file.string(), "(file)", "larger than 256 MiB: not a scene file");
  }
  JsonText text(static_cast<std::size_t>(std::filesystem::file_size(file, ec)));
  std::ifstream in(file, std::ios::binary);
  if (ec || !in.read(text.data(), static_cast<std::streamsize>(text.view().size()))) {
    throw SceneError(file.string(), "(file)", "cannot read the file");
  }
  return ReadScene(text, file.string(), file.parent_path());
}

}  // namespace twinraster
