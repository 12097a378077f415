#include "cli/io_arguments.hpp"

#include "base/usage_error.hpp"
#include "image/staged_file.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace twinraster {

namespace {
// The same bound LoadScene() puts on a file: far beyond any scene a person writes.
constexpr std::size_t kMaxSceneBytes = std::size_t{256} << 20;
constexpr const char* kStdinName = "<stdin>";
}  // namespace

std::string Suffixed(const std::string& out, const std::string& suffix) {
  std::filesystem::path p = out;
  const std::string extension = p.extension().string();
  p.replace_extension();
  p += "-" + suffix + extension;
  return p.string();
}

bool IsStandardStream(std::string_view argument) { return argument == "-"; }

Scene LoadSceneArgument(const std::string& argument, const SceneChoice& choice) {
  if (!IsStandardStream(argument)) return LoadSceneOrObj(argument, choice);
  std::string text;
  char buffer[1 << 16];
  for (;;) {
    const std::size_t n = std::fread(buffer, 1, sizeof buffer, stdin);
    text.append(buffer, n);
    if (text.size() > kMaxSceneBytes) throw SceneError(kStdinName, "(file)", "larger than 256 MiB: not a scene file");
    if (n < sizeof buffer) break;
  }
  if (std::ferror(stdin)) throw SceneError(kStdinName, "(file)", std::string("read error: ") + std::strerror(errno));
  Scene scene = ParseScene(text, kStdinName);
  ApplyChoice(scene, kStdinName, choice);
  return scene;
}

void ExpectPngName(const std::string& option, const std::string& name) {
  std::string extension = name.size() >= 4 ? name.substr(name.size() - 4) : "";
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (extension != ".png" || name.size() == 4 || name[name.size() - 5] == '/') {
    throw UsageError(option + " \"" + name + "\": the output must be a file name ending in .png");
  }
}

bool StandardOutputIsTerminal() { return ::isatty(STDOUT_FILENO) == 1; }

void WriteStandardOutput(std::string_view bytes) {
  if (std::fwrite(bytes.data(), 1, bytes.size(), stdout) != bytes.size() || std::fflush(stdout) != 0) {
    throw FileError(std::string("standard output: cannot write: ") + std::strerror(errno));
  }
}

}  // namespace twinraster
