// One scene's run, the whole pipeline on one screen: draw list, the backends' draws, the
// comparison, the judgement and the verdict. Scene in, RunResult out. It reads no file and writes
// none, prints nothing and picks no exit code: cli/ does those, from the result.
#pragma once

#include "run/backend_draws.hpp"
#include "run/run_record.hpp"
#include "scene/scene.hpp"

#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace twinraster::run {

enum class Backends { kBoth, kGpu, kCpu };

struct RunOptions {
  Backends backends = Backends::kBoth;
  Rules rules = Rules::kVulkan;  // kBook draws on the CPU only, by the chapter's demos, and is never judged
  bool verify = false;           // judge the image drawn (the GPU's when there is one) even when nothing differs
  bool map = false;              // keep the judgement's map (RunResult::map)
  unsigned threads = 0;          // the twin's; 0: as CpuOptions::threads says
  // The device asked for (--device). With Backends::kCpu no device is opened, and the twin's rules
  // are chosen by this name (twin_rules::ChooseTwinRulesByName; a name it has none for throws UsageError).
  std::string device;
};

// Reports what the run is doing, for a progress line: "gpu: drawing on Vulkan...".
using StatusLine = std::function<void(std::string_view)>;

struct RunResult {
  RunRecord record;
  std::vector<Image> images;  // one per record.backends, in its order; empty for a backend that did not draw
  std::vector<verify::DrawnBy> drawn_by;  // likewise: the PNG notes of each image
  std::optional<Image> diff;              // when the two images differ
  std::optional<Image> map;               // the judgement's map, when RunOptions::map and an image was judged
};

// `source` names the scene in the record and in a crash's problem. `gpu` draws every GPU image
// (unused by --backend cpu and the book). Throws GpuUnavailable, UsageError for a device asked by a
// name the twin has no rules for (with Backends::kCpu), std::invalid_argument for a list
// a renderer refuses, and book::BookRulesError for a scene the demos cannot draw.
RunResult RunScene(const Scene& scene, const std::string& source, const RunOptions& options, GpuSession& gpu,
                   const StatusLine& status = {});

}  // namespace twinraster::run
