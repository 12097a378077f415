#include "moving_page/self_contained_scene.hpp"

#include "scene/scene_error.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

namespace twinraster::moving_page {

namespace {

using Json = nlohmann::ordered_json;  // keys stay in the order the file writes them

std::string LowerExtension(const std::string& argument) {
  std::string extension = std::filesystem::path(argument).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

std::vector<std::uint8_t> ReadBytes(const std::filesystem::path& file, const std::string& scene) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw SceneError(scene, "", "cannot read \"" + file.string() + "\" to carry it in the page");
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Each model's "obj" path becomes the file's bytes (one already a data: URI stays as written); a
// model read from glTF is not carried yet.
std::string InlineModels(Json& models, const std::filesystem::path& directory, const std::string& scene) {
  if (!models.is_object()) return {};
  for (auto& [name, model] : models.items()) {
    if (!model.is_object()) continue;
    if (model.contains("gltf")) {
      return "model \"" + name + "\" is read from a glTF file, which the page does not carry yet";
    }
    const auto obj = model.find("obj");
    if (obj == model.end() || !obj->is_string() || obj->get<std::string>().starts_with("data:")) continue;
    const std::vector<std::uint8_t> bytes = ReadBytes(directory / obj->get<std::string>(), scene);
    *obj = "data:model/obj;base64," + Base64(bytes);
  }
  return {};
}

// --size resized the canvas and grew the viewport (ResizeCanvas): the file says so too.
void ApplySize(Json& json, const Scene& loaded) {
  json["canvas"]["width"] = loaded.canvas.width;
  json["canvas"]["height"] = loaded.canvas.height;
  json["viewport"]["width"] = loaded.viewport.width;
  json["viewport"]["height"] = loaded.viewport.height;
}

}  // namespace

std::string Base64(std::span<const std::uint8_t> bytes) {
  static constexpr char kDigits[] = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::string text;
  text.reserve((bytes.size() + 2) / 3 * 4);
  for (std::size_t i = 0; i < bytes.size(); i += 3) {
    const std::size_t left = bytes.size() - i;
    const std::uint32_t group = std::uint32_t{bytes[i]} << 16 | (left > 1 ? std::uint32_t{bytes[i + 1]} << 8 : 0) |
                                (left > 2 ? std::uint32_t{bytes[i + 2]} : 0);
    text += kDigits[group >> 18 & 63];
    text += kDigits[group >> 12 & 63];
    text += left > 1 ? kDigits[group >> 6 & 63] : '=';
    text += left > 2 ? kDigits[group & 63] : '=';
  }
  return text;
}

SelfContainedScene MakeSelfContainedScene(const std::string& argument, const Scene& loaded, const SceneChoice& choice) {
  if (argument == "-") return {{}, "the scene came from standard input; the page carries a scene file"};
  const std::string extension = LowerExtension(argument);
  if (extension == ".obj") return {{}, "SCENE is an OBJ file on its own, not a scene file naming it"};
  if (extension == ".gltf" || extension == ".glb")
    return {{}, "SCENE is a glTF file, which the page does not carry yet"};
  const std::vector<std::uint8_t> text = ReadBytes(argument, argument);
  Json json = Json::parse(text.begin(), text.end(), nullptr, false);
  if (json.is_discarded() || !json.is_object()) return {{}, "nlohmann's JSON parser does not read the scene file"};
  if (auto models = json.find("models"); models != json.end()) {
    std::string why_not = InlineModels(*models, std::filesystem::path(argument).parent_path(), argument);
    if (!why_not.empty()) return {{}, why_not};
  }
  if (choice.size) ApplySize(json, loaded);
  return {json.dump(2, ' ', false, Json::error_handler_t::replace), {}};
}

}  // namespace twinraster::moving_page
