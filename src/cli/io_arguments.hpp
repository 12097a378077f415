// Files and streams named on the command line: SCENE is a scene file, an OBJ file (framed by a
// default scene) or - (a scene on standard input); an output PNG is a .png file (written whole,
// then renamed into place) or - (standard output); an image to read is a file, never -. It does
// not check where outputs may go (output_paths.hpp).
#pragma once

#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

#include <string>
#include <string_view>

namespace twinraster::cli {

// "-" as SCENE or as an output: the standard stream, as in most command-line tools.
bool IsStandardStream(std::string_view argument);

// Reads the scene file, the OBJ file (a name ending in .obj, in any case: SceneForObj), the glTF
// file (.gltf or .glb: SceneForGltf), with `choice` applied, or a scene
// on standard input for "-" (named <stdin> in errors, its OBJ paths relative to the current
// directory); throws SceneError.
Scene LoadSceneArgument(const std::string& argument, const SceneChoice& choice = {});

// Throws UsageError unless `name` ends in .png (in any case): "<option> <name>: ...".
void ExpectPngName(const std::string& option, const std::string& name);

// Throws UsageError when an image to read is "-": verify and compare read PNG files only (verify
// writes its map beside the file), so - is refused rather than opened as a file of that name.
void ExpectImageFile(const std::string& argument, const std::string& name);

// "out.png" -> "out-gpu.png": the name of a file written beside `out` (render's per-backend,
// diff and map images, verify's map).
std::string Suffixed(const std::string& out, const std::string& suffix);

bool StandardOutputIsTerminal();
// All of `bytes` to standard output, flushed; throws FileError naming standard output.
void WriteStandardOutput(std::string_view bytes);

}  // namespace twinraster::cli
