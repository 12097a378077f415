// The scene a moving page carries: the scene file's own JSON (keys in the order written, every
// number as the file writes it), each OBJ model's file inlined as a base64 data: URI, and the
// command line's --size applied, so that the page reads no other file and a state it saves is a
// scene file `twinraster render` draws as it is. It does not carry a glTF file, an OBJ file on its
// own or a scene read from standard input: for those it says why the page cannot move.
#pragma once

#include "scene/scene.hpp"
#include "scene/scene_choice.hpp"

#include <cstdint>
#include <span>
#include <string>

namespace twinraster::moving_page {

// Exactly one of the two is set: the scene's JSON text, or one line saying why there is none.
struct SelfContainedScene {
  std::string json;
  std::string why_not;
};

// `argument` is SCENE as the command line gave it; `loaded` the scene read from it with `choice`
// applied (its canvas and viewport are what --size made of them). Throws SceneError when a file
// the scene names cannot be read.
SelfContainedScene MakeSelfContainedScene(const std::string& argument, const Scene& loaded, const SceneChoice& choice);

// RFC 4648 base64, with padding and no line breaks.
std::string Base64(std::span<const std::uint8_t> bytes);

}  // namespace twinraster::moving_page
