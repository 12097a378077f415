// What the command line chooses of a scene as it is read (--camera, --scene, --size), and the
// canvas resized to a chosen size without stretching the picture. It reads no file.
#pragma once

#include "scene/scene.hpp"

#include <cstdint>
#include <optional>
#include <string>

namespace twinraster {

struct CanvasSize {
  std::uint32_t width = 0, height = 0;  // Cw x Ch, each in 1..kMaxCanvasSize
};

struct SceneChoice {
  std::optional<std::string> camera;  // a glTF file's camera: its index in "cameras", or its name
  std::optional<std::size_t> scene;   // a glTF file's scene: its index in "scenes"
  std::optional<CanvasSize> size;     // the canvas, for any scene
};

// Cw x Ch becomes `size`, and the viewport grows in width or in height (never shrinks) to the
// canvas's aspect ratio, so that everything the scene showed is still shown, unstretched, with
// more of the world beside it. d, the depth range and the camera stay.
void ResizeCanvas(Scene& scene, CanvasSize size);

}  // namespace twinraster
