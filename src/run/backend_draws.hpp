// Each backend's draw of one scene as a run makes it, and as the bench times it: the GPU (in a
// child process), the CPU twin, the chapter's demos. Each returns its image with a record of where
// it ran and how long it took. It does not choose backends, compare or judge (run_scene.hpp does)
// and writes nothing.
#pragma once

#include "chain/draw_list.hpp"
#include "cpu/raster_rules.hpp"
#include "gpu/isolated_gpu.hpp"
#include "image/image.hpp"
#include "run/run_record.hpp"
#include "scene/scene.hpp"
#include "twin_rules/twin_rules.hpp"
#include "verify/drawn_by.hpp"

#include <optional>
#include <string>

namespace twinraster::run {

struct BackendRun {
  BackendRecord record;
  Image image;
  verify::DrawnBy drawn_by;  // the device's name and rasterization: the judgement's rules, the PNG's notes
};

// The Vulkan device of a batch: one child process (gpu/isolated_gpu.hpp) serves every scene until
// its driver crashes; the next scene then gets a fresh one. Made on the first GPU draw only.
class GpuSession {
 public:
  explicit GpuSession(gpu::IsolationOptions options) : options_(std::move(options)) {}
  gpu::IsolatedGpuResult Render(const DrawList& list);
  // Render in two halves (gpu/isolated_gpu.hpp), so that the twin can draw while the child does.
  void Submit(const DrawList& list);
  gpu::IsolatedGpuResult Collect();
  // The device the living child draws on, known once it has answered a list; empty otherwise.
  gpu::DeviceIdentity KnownDevice() const;

 private:
  gpu::IsolationOptions options_;
  std::optional<gpu::GpuProcess> process_;
};

// Throws GpuUnavailable without a device, and std::invalid_argument for a list the renderer
// refuses. A crash or a timeout is a result: status kCrashed or kTimedOut, the problem naming
// `source`, no image; `device` is still known when the child got that far.
BackendRun DrawOnGpu(const DrawList& list, GpuSession& gpu, const std::string& source, gpu::DeviceIdentity& device);
// The same for a list submitted earlier (GpuSession::Submit).
BackendRun CollectFromGpu(GpuSession& gpu, const std::string& source, gpu::DeviceIdentity& device);

// What the twin's choice of rules reads of a device (twin_rules/twin_rules.hpp).
twin_rules::DeviceFacts FactsOf(const gpu::DeviceIdentity& device);

// The twin, with the arithmetic of the lavapipe it copies.
BackendRun DrawOnTwin(const DrawList& list, const cpu::RasterRules& rules, unsigned threads);

// The chapter's demos, on one thread; throws book::BookRulesError for a scene they cannot draw.
BackendRun DrawByTheBook(const Scene& scene);

}  // namespace twinraster::run
