#include "run/backend_draws.hpp"

#include "base/stopwatch.hpp"
#include "book/book_renderer.hpp"
#include "cpu/cpu_renderer.hpp"

#include <stdexcept>

namespace twinraster::run {

namespace {

// The twin and the book report themselves as the twin does: the subpixel bits of the device its
// rules copy (the book: lavapipe's), strict lines.
verify::DrawnBy TwinDrawnBy(const cpu::RasterRules& rules) {
  const cpu::TwinLimits limits = cpu::TwinDeviceLimits(rules);
  return {"CPU twin", {.subpixel_bits = limits.subpixel_bits, .strict_lines = limits.strict_lines}};
}

}  // namespace

gpu::IsolatedGpuResult GpuSession::Render(const DrawList& list) {
  Submit(list);
  return Collect();
}

void GpuSession::Submit(const DrawList& list) {
  if (!process_) process_.emplace(options_);
  process_->Submit(list);
}

gpu::IsolatedGpuResult GpuSession::Collect() { return process_->Collect(); }

gpu::DeviceIdentity GpuSession::KnownDevice() const { return process_ ? process_->device() : gpu::DeviceIdentity{}; }

BackendRun DrawOnGpu(const DrawList& list, GpuSession& gpu, const std::string& source, gpu::DeviceIdentity& device) {
  gpu.Submit(list);
  return CollectFromGpu(gpu, source, device);
}

BackendRun CollectFromGpu(GpuSession& gpu, const std::string& source, gpu::DeviceIdentity& device) {
  BackendRun run;
  run.record.backend = Backend::kGpu;
  gpu::IsolatedGpuResult r = gpu.Collect();
  device = r.device;
  run.drawn_by = {r.device.name, {.subpixel_bits = int(r.device.subpixel_bits), .strict_lines = r.device.strict_lines}};
  run.record.detail = r.device.name.empty() ? "no device" : r.device.name;
  run.record.driver = r.device.driver_info;
  switch (r.outcome) {
    case gpu::GpuOutcome::kRendered: break;
    case gpu::GpuOutcome::kUnavailable: throw gpu::GpuUnavailable(r.problem);
    case gpu::GpuOutcome::kBadList: throw std::invalid_argument(r.problem);
    case gpu::GpuOutcome::kCrashed:
    case gpu::GpuOutcome::kTimedOut:
      run.record.status = r.outcome == gpu::GpuOutcome::kCrashed ? BackendStatus::kCrashed : BackendStatus::kTimedOut;
      run.record.problem = r.problem + " on " + source;
      return run;
  }
  run.image = std::move(r.image);
  // Set-up is everything before the draw: instance, device and pipeline, then buffers.
  run.record.setup_ms = r.device_ms + r.timings.setup_ms;
  run.record.draw_ms = r.timings.draw_ms;
  run.record.readback_ms = r.timings.readback_ms;
  run.record.isolation_ms = r.isolation_ms;
  return run;
}

twin_rules::DeviceFacts FactsOf(const gpu::DeviceIdentity& device) {
  return {.name = device.name,
          .driver_info = device.driver_info,
          .driver_id = device.driver_id,
          .driver_version = device.driver_version,
          .subpixel_bits = device.subpixel_bits};
}

BackendRun DrawOnTwin(const DrawList& list, const cpu::RasterRules& rules, unsigned threads) {
  BackendRun run;
  run.record.backend = Backend::kCpu;
  cpu::CpuOptions options;
  options.threads = threads;
  options.rules = rules;
  cpu::CpuTimings t;
  run.image = cpu::RenderOnCpu(list, options, &t);
  run.drawn_by = TwinDrawnBy(rules);
  run.record.threads = t.threads;
  run.record.detail = "CPU twin, " + std::to_string(t.threads) + (t.threads == 1 ? " thread" : " threads");
  run.record.setup_ms = t.setup_ms, run.record.draw_ms = t.draw_ms, run.record.readback_ms = t.readback_ms;
  return run;
}

BackendRun DrawByTheBook(const Scene& scene) {
  BackendRun run;
  run.record.backend = Backend::kCpu;
  run.record.detail = "book rules: the chapter's demos, 1 thread";
  Stopwatch clock;
  run.image = book::RenderScene(scene);
  run.record.draw_ms = clock.Milliseconds();  // the demos draw straight into the image: all of it is drawing
  run.drawn_by = TwinDrawnBy({});
  return run;
}

}  // namespace twinraster::run
