// `twinraster render`'s arguments as parsed (command_render.cpp declares them on the parser), and
// the run's typed options made from them; every step of render reads these. It parses and checks
// nothing itself (render_option_checks.hpp checks them).
#pragma once

#include "cli/scene_choice_options.hpp"
#include "files/png_file.hpp"
#include "run/run_scene.hpp"

#include <optional>
#include <string>
#include <vector>

namespace twinraster::cli {

struct RenderArguments {
  std::vector<std::string> scenes;
  std::optional<std::string> output;     // one scene: OUT.png, - or a directory; several: a directory
  std::optional<std::string> directory;  // where each scene's files go, named after it (CheckOutput)
  int png_level = files::kPngFastest;
  std::string backend = "both";
  bool backend_given = false;  // --backend on the command line, rather than the default
  std::string rules = "vulkan";
  bool wireframe = false;  // --wireframe: as if every scene said "wireframe": true
  bool verify = false;     // --verify: judge the image just drawn by what Vulkan allows
  bool json = false;
  std::string device;
  double timeout_seconds = 600;  // the GPU process's time limit; 0: none
  unsigned threads = 0;
  bool quiet = false;
  std::optional<std::string> report;  // --report DIR: index.html and thumbnails
  std::optional<std::string> junit;   // --junit FILE
  SceneChoiceArguments choice;        // --camera, --scene, --size
  run::RunOptions run;                // the words above as the run stage takes them (ResolveOptions)
};

}  // namespace twinraster::cli
