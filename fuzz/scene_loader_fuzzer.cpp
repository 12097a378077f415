// libFuzzer target for the scene loader: any bytes either load into a scene or are refused with a
// SceneError; anything else (another exception, a crash, a leak, undefined behaviour, a hang) is
// a finding. A scene that loads must also keep the promises src/scene/scene.hpp makes ("already
// validated by the loader"), which every later stage relies on; a broken one traps.
#include "scene/scene.hpp"
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace {

void Check(bool promise) {
  if (!promise) __builtin_trap();
}

void CheckScene(const twinraster::Scene& scene) {
  Check(scene.canvas.width >= 1 && scene.canvas.width <= twinraster::kMaxCanvasSize);
  Check(scene.canvas.height >= 1 && scene.canvas.height <= twinraster::kMaxCanvasSize);
  Check(scene.depth.far > scene.depth.near);
  for (const twinraster::Model& model : scene.models) {
    for (const twinraster::Triangle& triangle : model.triangles) {
      for (const std::uint32_t v : triangle.v) Check(v < model.vertices.size());
    }
    Check(model.triangle_normals.empty() || model.triangle_normals.size() == model.triangles.size());
    for (const auto& corners : model.triangle_normals) {
      for (const std::uint32_t n : corners) Check(n == twinraster::kNoNormal || n < model.normals.size());
    }
    Check(scene.lighting || model.shading == twinraster::Shading::kUnlit);
  }
  if (scene.lighting) {
    Check(scene.lighting->ambient >= 0);
    for (const twinraster::Light& light : scene.lighting->lights) Check(light.intensity >= 0);
  }
  Check(scene.instances.size() <= twinraster::kMaxInstances);
  for (const twinraster::Instance& instance : scene.instances) Check(instance.model < scene.models.size());
  for (const twinraster::InstanceGrid& grid : scene.grids) {
    Check(grid.first <= scene.instances.size() && grid.copies() <= scene.instances.size() - grid.first);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    CheckScene(twinraster::ParseScene(text, "fuzz.json"));
  } catch (const twinraster::SceneError&) {
    // The expected way to refuse bad input.
  }
  return 0;
}
