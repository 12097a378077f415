// libFuzzer target for the scene loader: any bytes either load into a scene or are refused with a
// SceneError; anything else (another exception, a crash, a leak, undefined behaviour, a hang) is
// a finding.
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    const twinraster::Scene scene = twinraster::ParseScene(text, "fuzz.json");
    // A scene that loads has what every later stage relies on.
    if (scene.canvas.width == 0 || scene.canvas.height == 0) __builtin_trap();
    for (const twinraster::Instance& instance : scene.instances) {
      if (instance.model >= scene.models.size()) __builtin_trap();
    }
  } catch (const twinraster::SceneError&) {
    // The expected way to refuse bad input.
  }
  return 0;
}
