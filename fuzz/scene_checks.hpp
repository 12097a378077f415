// What every fuzzer checks of a scene that loaded: the promises src/scene/scene.hpp makes ("already
// validated by the loader"), which every later stage relies on. A broken promise traps, which
// libFuzzer reports as a finding. It loads nothing itself.
#pragma once

#include "chain/matrices.hpp"
#include "chain/normals.hpp"
#include "scene/scene.hpp"

#include <cmath>
#include <cstdint>

namespace twinraster::fuzz {

inline void Check(bool promise) {
  if (!promise) __builtin_trap();
}

inline void CheckScene(const twinraster::Scene& scene) {
  Check(scene.canvas.width >= 1 && scene.canvas.width <= twinraster::kMaxCanvasSize);
  Check(scene.canvas.height >= 1 && scene.canvas.height <= twinraster::kMaxCanvasSize);
  Check(scene.depth.far > scene.depth.near && scene.depth.near >= 0 && !std::isnan(scene.depth.far));
  Check(scene.viewport.width > 0 && scene.viewport.height > 0 && std::isfinite(scene.viewport.width) &&
        std::isfinite(scene.viewport.height));
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
  for (const twinraster::Instance& instance : scene.instances) {
    Check(instance.model < scene.models.size());
    Check(!instance.transform.steps || !instance.transform.steps->empty());
    // A lit instance's normal matrix exists and is finite in float, or the draw list could not be
    // built (an internal error, exit 4, where the loader should have named the place).
    if (scene.lighting && scene.models[instance.model].shading != twinraster::Shading::kUnlit) {
      Check(twinraster::NormalMatrix(twinraster::ModelMatrix(instance.transform)).has_value());
    }
  }
  for (const twinraster::InstanceGrid& grid : scene.grids) {
    Check(grid.first <= scene.instances.size() && grid.copies() <= scene.instances.size() - grid.first);
  }
}

}  // namespace twinraster::fuzz
