// libFuzzer target for the glTF reader: any bytes, as a .gltf or a .glb, either become a scene or
// are refused with a SceneError; anything else (another exception, a crash, a leak, undefined
// behaviour, a hang, memory out of proportion) is a finding. No file is read beside the input:
// a URI naming one is refused, as a data: URI is decoded. A scene that loads keeps scene.hpp's
// promises (scene_checks.hpp).
#include "scene/gltf_document.hpp"
#include "scene/gltf_scene.hpp"
#include "scene/scene_error.hpp"
#include "scene_checks.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::vector<std::uint8_t> bytes(data, data + size);
  try {
    const twinraster::GltfDocument doc = twinraster::ParseGltf(bytes, "fuzz.glb", {});
    twinraster::fuzz::CheckScene(twinraster::GltfScene(doc, {}, "fuzz"));
  } catch (const twinraster::SceneError&) {
    // The expected way to refuse bad input.
  }
  return 0;
}
