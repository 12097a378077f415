// Random lit scenes from a seed, built in code: lumpy spheres (with and without per-corner
// normals, flat, Gouraud or unlit), non-uniform and negative scales, directional and point
// lights (some inside a mesh), cameras outside and inside the meshes; the same with vertex colours.
#pragma once

#include "scene/scene.hpp"

#include <cstdint>

namespace twinraster::test {

Scene RandomLitScene(std::uint32_t seed);

// RandomLitScene(seed) with a random colour on every vertex of every model (glTF's COLOR_0), and
// for one seed in three no lighting at all, so that every model is unlit and its vertex colours
// are interpolated as they are.
Scene RandomVertexColourScene(std::uint32_t seed);

// A closed lumpy sphere of `rings` x `segments` quads (two triangles each), radius about 1; with
// `normals`, each corner names its own (perturbed) normal as an OBJ's vn would.
Model LumpySphere(std::uint32_t seed, int rings, int segments, bool normals, Shading shading);

}  // namespace twinraster::test
