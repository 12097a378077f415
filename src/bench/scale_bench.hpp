// `twinraster bench --scale`: the chapter's "one million cubes" at 1 k, 10 k, 100 k and 1 M
// instances, each stage timed (medians; the verifier's judgement too) with the process's peak
// memory, so that cost can be read against instance count; each size's frame written by every PNG
// encoder (png_bench.hpp); and, first, the fixed costs of a scene as whole processes
// (process_bench.hpp).
#pragma once

#include "bench/png_bench.hpp"
#include "bench/process_bench.hpp"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::bench {

struct ScaleRow {
  std::size_t instances = 0, triangles = 0;
  std::size_t json_bytes = 0;  // the scene file, every instance written out
  unsigned threads = 0;        // the CPU twin's
  // Medians, milliseconds. load: parsing the JSON into a Scene; chain: the host's F per instance
  // (the draw list); gpu_*: lavapipe; twin_*: the CPU twin; png: encoding the twin's image.
  double load_ms = 0, chain_ms = 0, gpu_setup_ms = 0, gpu_draw_ms = 0, twin_setup_ms = 0, twin_draw_ms = 0, png_ms = 0;
  // lavapipe with F pushed per draw (one draw per instance, Listing 10-5), set-up plus draw, to
  // set against gpu_setup_ms + gpu_draw_ms (instanced): where the two cross over.
  double gpu_per_draw_ms = 0;
  // The verifier judging the twin's image (lavapipe's 8 subpixel bits): what checking a frame
  // costs at this size, beside drawing it.
  double verify_ms = 0;
  double peak_mib = 0;     // the process's peak resident memory once this size is done (sizes run in increasing order)
  bool identical = false;  // lavapipe's image equals the twin's
  std::vector<PngEncoding> png_encoders;  // the twin's frame, by each encoder
};

struct ScaleOptions {
  std::vector<std::size_t> counts = {1'000, 10'000, 100'000, 1'000'000};
  int runs = 3;
  std::uint32_t width = 1920, height = 1080;
  std::function<void(const ScaleRow& row, std::size_t done, std::size_t total)> on_row;
  std::optional<ProcessBenchOptions> processes;  // the fixed costs too, when given
};

struct ScaleResult {
  std::optional<ProcessTimes> processes;
  std::vector<ScaleRow> rows;
  std::string machine;
  int runs = 0;
  std::uint32_t width = 0, height = 0;  // every size's frame
};

// Cubes in a centred grid as close to a cube as the count allows, each written out as its own
// instance, seen whole from above a corner. Throws GpuUnavailable without a Vulkan device.
ScaleResult RunScaleBench(const ScaleOptions& options);

}  // namespace twinraster::bench
