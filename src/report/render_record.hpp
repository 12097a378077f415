// One scene's render as every output reads it: render's text and --json, the batch page and the
// JUnit file. `render` fills it once; the outputs only format it.
#pragma once

#include "cpu/twin_rules.hpp"
#include "image/image_compare.hpp"
#include "verify/verification.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::report {

// One backend's run: its image's file, where it ran, how long each part took.
struct BackendRecord {
  std::string name;    // "gpu" or "cpu"
  std::string detail;  // device name, or thread count
  std::string driver;  // gpu: the driver's own version string (driverInfo)
  std::string output;  // a file, or "-" for standard output; empty when nothing was drawn
  double setup_ms = 0, draw_ms = 0, readback_ms = 0, png_ms = 0;
  double isolation_ms = 0;  // gpu: the child process's cost (fork, pipe, shared pixels, wait)
  // gpu: "rendered", "crashed" or "timed out"; `problem` says how, with the scene.
  std::string status = "rendered";
  std::string problem;
  bool Drawn() const { return status == "rendered"; }
};

struct RenderRecord {
  std::string scene;  // the argument, as given
  std::string name;   // the scene's name, which its files are named after
  // A scene that could not be read or written: the message (file, place, problem); nothing else
  // below is filled in then.
  std::string error;
  std::string rules = "vulkan";
  bool wireframe = false;
  std::uint32_t width = 0, height = 0;
  std::size_t instances = 0, triangles = 0;
  double load_ms = 0;
  std::vector<BackendRecord> backends;  // in drawing order: gpu first
  std::optional<cpu::TwinRules> twin;
  std::optional<Comparison> comparison;  // gpu against cpu, when both drew
  std::string diff;                      // the diff image, when one was written
  // The verifier's judgement (its per-pixel classes dropped: the map holds them), of the image
  // named `judged`; `map` is the map's file when one was written.
  std::optional<verify::Verification> verification;
  std::string judged;
  std::string map;
  double verify_ms = 0;
  int exit_code = 0;      // what this scene alone would make `render` exit with
  double total_ms = 0;    // reading the scene to writing its files

  const BackendRecord* Backend(const std::string& backend_name) const;
  // The twin copies this lavapipe: identical images were promised.
  bool TwinPromised() const { return twin && twin->exact; }
};

// What a reader of a batch wants first: did it break, and how.
enum class Verdict {
  kError,      // bad input, or an output that could not be written
  kCrashed,    // the Vulkan driver crashed or timed out
  kDiffering,  // the images differ where the twin promised they would not, or the verifier found a violation
  kInconclusive,  // the images differ, or one was judged, and the verifier could not tell (neither pass nor fail)
  kVerified,   // the images differ, or one was judged, and the verifier passed it
  kIdentical,  // gpu and cpu agree bit for bit
  kRendered,   // one backend drew, nothing was compared or judged
};

Verdict VerdictOf(const RenderRecord& record);
const char* VerdictName(Verdict verdict);  // "error", "crashed", ...
bool IsFailure(Verdict verdict);           // error, crashed, differing
// One line on why: the problem, the verifier's sentence, or the comparison's.
std::string VerdictReason(const RenderRecord& record);

}  // namespace twinraster::report
