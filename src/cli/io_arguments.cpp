#include "cli/io_arguments.hpp"

#include "base/usage_error.hpp"
#include "files/staged_file.hpp"
#include "scene/obj_scene.hpp"
#include "scene/scene_loader.hpp"

#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace twinraster::cli {

namespace {
// The same bound LoadScene() puts on a file: far beyond any scene a person writes.
constexpr std::size_t kMaxSceneBytes = std::size_t{256} << 20;
constexpr const char* kStdinName = "<stdin>";

// What text that is not JSON most likely is, for the hint below; "" when nothing stands out.
std::string_view LikelyKind(std::string_view text) {
  if (text.starts_with("glTF")) return "a binary glTF file (.glb)";
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (first == std::string_view::npos) return "";
  const std::string_view line = text.substr(first, text.find('\n', first) - first);
  // An OBJ file opens with a comment or one of its statements.
  for (const std::string_view start : {"#", "v ", "vn ", "vt ", "f ", "o ", "g ", "mtllib ", "usemtl ", "s "}) {
    if (line.starts_with(start)) return "an OBJ mesh";
  }
  return "";
}

// A syntax error in standard input (its place is a line, not a JSON path) is often an OBJ or glTF
// file piped in: standard input is read as a JSON scene only, which the message then says.
SceneError WithStdinHint(const SceneError& e, std::string_view text) {
  if (!e.where().starts_with("line ")) return e;
  const std::string_view kind = LikelyKind(text);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  if (kind.empty() && first != std::string_view::npos && text[first] == '{') return e;  // JSON, just broken
  std::string hint = " (- reads a JSON scene file only";
  if (!kind.empty()) hint += "; this looks like " + std::string(kind) + ": give its file name instead";
  return SceneError(e.file(), e.where(), e.problem() + hint + ")");
}

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
  try {
    Scene scene = ParseScene(text, kStdinName);
    ApplyChoice(scene, kStdinName, choice);
    return scene;
  } catch (const SceneError& e) {
    throw WithStdinHint(e, text);
  }
}

void ExpectImageFile(const std::string& argument, const std::string& name) {
  if (IsStandardStream(name)) {
    throw UsageError(argument +
                     " -: images are read from files, not from standard input; write it to a file first "
                     "(render -o FILE.png)");
  }
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
    throw files::FileError(std::string("standard output: cannot write: ") + std::strerror(errno));
  }
}

}  // namespace twinraster::cli
