#include "scene/scene_choice.hpp"

namespace twinraster {

void ResizeCanvas(Scene& scene, CanvasSize size) {
  const double aspect = static_cast<double>(size.width) / size.height;
  Viewport& v = scene.viewport;
  if (v.width / v.height < aspect) {
    v.width = v.height * aspect;
  } else {
    v.height = v.width / aspect;
  }
  scene.canvas.width = size.width;
  scene.canvas.height = size.height;
}

}  // namespace twinraster
