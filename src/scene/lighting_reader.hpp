// Reads a scene's "lighting": an ambient term and directional or point lights, in the diffuse
// model of Computer Graphics from Scratch (see Light in scene.hpp).
#pragma once

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace twinraster {

// {"ambient": a, "lights": [{"type": "directional", "direction": [x, y, z], "intensity": i},
//                           {"type": "point", "position": [x, y, z], "intensity": i}]}
Lighting ReadLighting(const JsonReader& r);

}  // namespace twinraster
