// The scenes the verifier's tests judge, built one way for all of them: every shipped scene and
// mesh, and the random scenes, each filled or as a wireframe, with its draw list. It draws nothing.
#pragma once

#include "chain/draw_list.hpp"
#include "scene/scene.hpp"

#include <cstdint>
#include <filesystem>
#include <vector>

namespace twinraster::test {

struct Drawn {
  Scene scene;
  DrawList list;
};

std::vector<std::filesystem::path> ShippedScenesAndMeshes();  // the shipped scenes, then scenes/meshes/*.obj
Drawn ShippedScene(const std::filesystem::path& file, bool wireframe);
Drawn RandomScene(std::uint32_t seed, bool wireframe);  // twin/random_scene's scene `seed`

}  // namespace twinraster::test
