// libFuzzer target for the scene loader: any bytes either load into a scene or are refused with a
// SceneError; anything else (another exception, a crash, a leak, undefined behaviour, a hang) is
// a finding. A scene that loads must also keep the promises src/scene/scene.hpp makes
// (scene_checks.hpp); a broken one traps.
#include "scene/scene_error.hpp"
#include "scene/scene_loader.hpp"
#include "scene_checks.hpp"

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string_view text(reinterpret_cast<const char*>(data), size);
  try {
    twinraster::fuzz::CheckScene(twinraster::ParseScene(text, "fuzz.json"));
  } catch (const twinraster::SceneError&) {
    // The expected way to refuse bad input.
  }
  return 0;
}
