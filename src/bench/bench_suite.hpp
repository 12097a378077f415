// `twinraster bench`: runs a fixed suite of scenes through every way of computing the chain and
// both renderers, timing each (medians) and measuring its error against the ground truth.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace twinraster::bench {

struct BenchRow {
  std::string scene;
  // A VertexMethod's name, or for whole frames "cpu-twin" / "lavapipe", "cpu-twin-swiftshader" (the
  // twin with SwiftShader's rules) / "swiftshader".
  std::string method;
  unsigned threads = 0;  // rasterizer threads for the frame time
  std::size_t vertices = 0, triangles = 0;
  std::uint32_t width = 0, height = 0;
  double vertex_ms = -1;             // median time of the vertex stage alone (-1: not separable, e.g. lavapipe)
  double frame_ms = 0;               // median time of the whole frame: vertex stage, clipping, rasterization
  double vertex_error_px = -1;       // max distance from the truth's framebuffer positions (-1: not measured)
  std::uint64_t image_error_px = 0;  // pixels that differ from the truth image
  std::optional<std::uint64_t> z_fighting_px;  // depth scenes: far plate showing where the near one should
  // Lit scenes: the largest channel difference (0..255) from the truth's colours inside its
  // triangles (error_metrics.hpp), and over how many pixels.
  std::optional<int> colour_error;
  std::uint64_t colour_pixels = 0;
};

struct BenchOptions {
  std::filesystem::path scenes_dir = "scenes";  // the suite: *.json, hard/*.json, bench/*.json
  int runs = 15;                                // timings are medians over this many runs
  std::optional<std::string> only;              // only scenes whose name contains this
  // Which rows to run: the vertex methods' names and the renderers' (BenchRow::method); empty
  // means all.
  std::vector<std::string> methods;
  // Called as each row is measured, in the order of BenchResult::rows: row number `done` (from 1)
  // of `total`. A whole run takes seconds to minutes, so a user can watch the rows come in.
  std::function<void(const BenchRow& row, std::size_t done, std::size_t total)> on_row;
};

struct BenchResult {
  std::vector<BenchRow> rows;
  std::string machine;  // CPU model and core count, Vulkan device
  int runs = 0;
  double seconds = 0;
};

// The middle value of `values` (the upper middle of an even count), for every bench's medians.
double Median(std::vector<double> values);

// "CPU model, N hardware threads; Vulkan: device", for the reports.
std::string MachineDescription(const std::string& device);

// Every name --methods accepts, in the order rows appear.
std::vector<std::string> BenchMethodNames();

BenchResult RunBench(const BenchOptions& options);

}  // namespace twinraster::bench
