#include "cli/scene_choice_options.hpp"

#include "base/usage_error.hpp"
#include "cli/parser_setup.hpp"

#include <CLI/CLI.hpp>

#include <charconv>
#include <iostream>

namespace twinraster::cli {

namespace {

std::optional<std::uint32_t> Side(std::string_view text) {
  std::uint32_t value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > kMaxCanvasSize) return {};
  return value;
}

}  // namespace

void AddSceneChoiceOptions(CLI::App& command, SceneChoiceArguments& a) {
  command
      .add_option("--camera", a.camera,
                  "a glTF file's camera: its index in \"cameras\", or its name (default: the\n"
                  "first camera node of the scene)")
      ->type_name("N|NAME");
  ExpectIndex(command.add_option("--scene", a.scene, "a glTF file's scene, counted from 0 (default: its \"scene\")")
                  ->type_name("N"));
  command
      .add_option("--size", a.size,
                  "the canvas, W x H pixels, for any scene; the view widens to the canvas's shape,\n"
                  "never cropped or stretched")
      ->type_name("WxH");
}

SceneChoice ChoiceOf(const SceneChoiceArguments& a) {
  SceneChoice choice{a.camera, a.scene, std::nullopt};
  if (a.size) {
    const std::string& s = *a.size;
    const std::size_t x = s.find_first_of("xX");
    const std::optional<std::uint32_t> w =
        x == std::string::npos ? std::nullopt : Side(std::string_view(s).substr(0, x));
    const std::optional<std::uint32_t> h =
        x == std::string::npos ? std::nullopt : Side(std::string_view(s).substr(x + 1));
    if (!w || !h) {
      throw UsageError("--size \"" + s + "\": expected WxH, two whole numbers of pixels in 1.." +
                       std::to_string(kMaxCanvasSize) + ", such as 800x600");
    }
    choice.size = CanvasSize{*w, *h};
  }
  return choice;
}

void PrintSceneNotes(const Scene& scene, const std::string& file) {
  for (const std::string& note : scene.notes) std::cerr << "twinraster: note: " << file << ": " << note << "\n";
}

}  // namespace twinraster::cli
