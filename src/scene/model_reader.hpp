// Reads a scene's model: JSON "vertices" and "triangles", or an OBJ file ("obj") in a "colour" or
// per-material "materials" colours; either with a "shading" for the scene's "lighting".
#pragma once

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

#include <filesystem>
#include <string>

namespace twinraster {

// A colour name in any case (the chapter's six, white, black, gray) or [r, g, b] with 0..255.
Rgb8 ReadColour(const JsonReader& r);

// "unlit", "flat" or "gouraud", as scene files write them.
const char* ShadingName(Shading shading);

// `directory`: where an "obj" path written relative starts (the scene file's directory; empty: the
// current one). `lit`: the scene has "lighting"; without it every model is unlit, and a model
// asking for another shading is an error. With it, a model's shading defaults to gouraud if its
// OBJ file gives normals (vn), flat otherwise.
Model ReadModel(const JsonReader& r, const std::string& name, const std::filesystem::path& directory, bool lit);

}  // namespace twinraster
