// One scene's run as every output reads it (render's text and --json, the batch page, the JUnit
// file): what each backend did, what was compared and judged, and the one verdict. It holds no
// pixels (run_scene.hpp's RunResult carries those until they are written) and formats nothing
// (run_report/ does).
#pragma once

#include "image/image_compare.hpp"
#include "run/verdict.hpp"
#include "twin_rules/twin_rules.hpp"
#include "verify/verification.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::run {

enum class Backend { kGpu, kCpu };
const char* BackendName(Backend backend);  // "gpu", "cpu": the outputs' names and file suffixes

enum class BackendStatus {
  kRendered,  // the image is there
  kCrashed,   // the Vulkan driver's process died
  kTimedOut,  // the Vulkan driver's process passed the time limit and was stopped
};
const char* StatusName(BackendStatus status);  // "rendered", "crashed", "timed out"

// One backend's run: where it ran, how long each part took, and the file its image went to.
struct BackendRecord {
  Backend backend = Backend::kCpu;
  std::string detail;    // device name, or thread count
  unsigned threads = 0;  // cpu: the twin's threads
  std::string driver;    // gpu: the driver's own version string (driverInfo)
  std::string output;    // a file, or "-" for standard output; empty when nothing was written
  double setup_ms = 0, draw_ms = 0, readback_ms = 0, png_ms = 0;
  double isolation_ms = 0;  // gpu: the child process's cost (fork, pipe, shared pixels, wait)
  BackendStatus status = BackendStatus::kRendered;
  std::string problem;  // how it crashed or timed out, naming the scene
  bool Drawn() const { return status == BackendStatus::kRendered; }
  const char* Name() const { return BackendName(backend); }
};

enum class Rules { kVulkan, kBook };
const char* RulesName(Rules rules);  // "vulkan", "book"

struct RunRecord {
  std::string scene;  // the argument, as given
  std::string name;   // the scene's name, which its files are named after
  // A scene that could not be read, drawn by the book or written: the message (file, place,
  // problem); nothing else below is filled in then.
  std::string error;
  Rules rules = Rules::kVulkan;
  bool wireframe = false;
  std::uint32_t width = 0, height = 0;
  std::size_t instances = 0, triangles = 0;
  double load_ms = 0;
  std::vector<BackendRecord> backends;  // in drawing order: gpu first
  std::optional<twin_rules::TwinRules> twin;
  std::optional<Comparison> comparison;  // gpu against cpu, when both drew
  std::string diff;                      // the diff image's file, when one was written
  // The verifier's judgement of the `judged` backend's image; its per-pixel classes are dropped
  // (the map holds them), so that a batch's records stay small.
  std::optional<verify::Verification> verification;
  std::optional<Backend> judged;
  std::string map;  // the map's file, when one was written
  double verify_ms = 0;
  Verdict verdict = Verdict::kRendered;  // VerdictOf(*this), decided once the run is done
  double total_ms = 0;                   // reading the scene to writing its files

  const BackendRecord* Find(Backend backend) const;
  BackendRecord* Find(Backend backend);
  bool Differ() const { return comparison && !comparison->Equal(); }
  // The twin copies this lavapipe: identical images were promised.
  bool TwinPromised() const { return twin && twin->exact; }
};

// What a run decides from its record: the outputs and the exit code read `RunRecord::verdict`,
// which holds this.
Verdict VerdictOf(const RunRecord& record);

// The record of a scene that failed before or while writing its files: verdict kError.
RunRecord ErrorRecord(const std::string& scene, const std::string& message);

}  // namespace twinraster::run
