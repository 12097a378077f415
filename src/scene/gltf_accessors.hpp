// Reads a glTF accessor's elements as the chain needs them: positions and normals in double,
// colours in [0, 1], indices as integers. Every element read was placed inside its buffer by
// gltf_document; these add no check of their own but the index values' (ReadIndices' caller).
// It does not apply sparse substitutions: primitives whose accessors are sparse are refused.
#pragma once

#include "scene/gltf_document.hpp"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <vector>

namespace twinraster {

std::vector<glm::dvec3> ReadVec3s(const GltfDocument& doc, const GltfAccessor& a);
// VEC3 colours get alpha 1; normalized integers are divided by their maximum, as the spec says.
std::vector<glm::dvec4> ReadColours(const GltfDocument& doc, const GltfAccessor& a);
std::vector<std::uint32_t> ReadIndices(const GltfDocument& doc, const GltfAccessor& a);

}  // namespace twinraster
