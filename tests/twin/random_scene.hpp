// Random scene files from a seed, for property tests: random models (cubes, blobs, slivers,
// sub-pixel and huge triangles), instances and transforms, cameras inside and outside the cloud.
#pragma once

#include <nlohmann/json.hpp>

#include <cstdint>

namespace twinraster::test {

// The scene as JSON, so that a failing case can be written out and replayed with the CLI.
nlohmann::ordered_json RandomSceneJson(std::uint32_t seed);

}  // namespace twinraster::test
