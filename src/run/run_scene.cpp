#include "run/run_scene.hpp"

#include "run/judge_image.hpp"
#include "twin_rules/lavapipe_path.hpp"
#include "twin_rules/twin_rules.hpp"

namespace twinraster::run {

namespace {

void Say(const StatusLine& status, std::string_view text) {
  if (status) status(text);
}

RunRecord SceneRecord(const Scene& scene, const std::string& source, const RunOptions& options) {
  RunRecord record;
  record.scene = source;
  record.name = scene.name;
  record.rules = options.rules;
  record.wireframe = options.rules == Rules::kBook || scene.wireframe;  // the demos draw wireframes only
  record.width = scene.canvas.width, record.height = scene.canvas.height;
  record.instances = scene.instances.size();
  for (const Instance& instance : scene.instances) record.triangles += scene.models[instance.model].triangles.size();
  return record;
}

// The twin with the rules of the device that drew (with no device, lavapipe's default release).
BackendRun Twin(const DrawList& list, const gpu::DeviceIdentity& device, const RunOptions& options,
                std::optional<twin_rules::TwinRules>& rules) {
  rules = twin_rules::ChooseTwinRules(FactsOf(device), twin_rules::DetectCpuPath());
  return DrawOnTwin(list, rules->rules, options.threads);
}

// The GPU's image, and the twin's when both are asked for: drawn meanwhile when the GPU process
// knows its device (every scene of a batch after its first), so that both cores work. Should the
// device that drew not be the one expected (a fresh process after a crash), the twin draws again
// by the right rules.
void DrawWithGpu(const DrawList& list, const RunOptions& options, GpuSession& gpu, RunRecord& record,
                 std::vector<BackendRun>& runs, const StatusLine& status) {
  Say(status, "gpu: drawing on Vulkan...");
  gpu.Submit(list);
  const gpu::DeviceIdentity expected = gpu.KnownDevice();
  std::optional<BackendRun> twin;
  std::optional<twin_rules::TwinRules> twin_rules;
  if (options.backends == Backends::kBoth && !expected.name.empty()) {
    try {
      Say(status, "cpu: drawing...");
      twin = Twin(list, expected, options, twin_rules);
    } catch (...) {
      gpu.Collect();  // nothing is left pending
      throw;
    }
  }
  gpu::DeviceIdentity device;
  runs.push_back(CollectFromGpu(gpu, record.scene, device));
  if (options.backends == Backends::kGpu) return;
  record.twin = twin_rules::ChooseTwinRules(FactsOf(device), twin_rules::DetectCpuPath());
  if (!twin || !(twin_rules->rules == record.twin->rules)) {
    Say(status, "cpu: drawing...");
    twin = DrawOnTwin(list, record.twin->rules, options.threads);
  }
  runs.push_back(std::move(*twin));
}

// Every backend asked for, GPU first. A GPU process that crashes is a result, and the twin still
// draws.
std::vector<BackendRun> Draw(const Scene& scene, const DrawList& list, const RunOptions& options, GpuSession& gpu,
                             RunRecord& record, const StatusLine& status) {
  std::vector<BackendRun> runs;
  if (options.rules == Rules::kBook) {
    Say(status, "cpu: drawing by the book's rules...");
    runs.push_back(DrawByTheBook(scene));
    return runs;
  }
  if (options.backends != Backends::kCpu) {
    DrawWithGpu(list, options, gpu, record, runs, status);
    return runs;
  }
  Say(status, "cpu: drawing...");
  if (options.device.empty()) {
    runs.push_back(Twin(list, gpu::DeviceIdentity{}, options, record.twin));
  } else {
    record.twin = twin_rules::ChooseTwinRulesByName(options.device, twin_rules::DetectCpuPath());
    runs.push_back(DrawOnTwin(list, record.twin->rules, options.threads));
  }
  return runs;
}

// The image the verifier judges: the GPU's when it drew, else the twin's; none for the book's
// rules, and none unless asked for or the two images differ (to say whether Vulkan allows that).
const BackendRun* Judged(const std::vector<BackendRun>& runs, const RunOptions& options, const RunRecord& record) {
  if (options.rules == Rules::kBook || !(options.verify || record.Differ())) return nullptr;
  const BackendRun* judged = nullptr;
  for (const BackendRun& run : runs) {
    if (run.record.Drawn() && (!judged || run.record.backend == Backend::kGpu)) judged = &run;
  }
  return judged;
}

void Judge(const Scene& scene, const DrawList& list, const BackendRun& run, const RunOptions& options,
           RunResult& result) {
  RunRecord& record = result.record;
  ImageJudgement j = JudgeImage(scene, list, run.image, run.drawn_by.rasterizes, options.map);
  record.verification = std::move(j.verification);
  record.verify_ms = j.verify_ms;
  record.judged = run.record.backend;
  result.map = std::move(j.map);
  record.verification->pixels = {};  // the map holds them
}

}  // namespace

RunResult RunScene(const Scene& scene, const std::string& source, const RunOptions& options, GpuSession& gpu,
                   const StatusLine& status) {
  RunResult result;
  RunRecord& record = result.record = SceneRecord(scene, source, options);
  const DrawList list = options.rules == Rules::kBook ? DrawList{} : BuildDrawList(scene);  // the book reads the scene
  std::vector<BackendRun> runs = Draw(scene, list, options, gpu, record, status);

  if (runs.size() == 2 && runs[0].record.Drawn() && runs[1].record.Drawn()) {
    Say(status, "comparing gpu and cpu...");
    record.comparison = CompareImages(runs[0].image, runs[1].image);
    if (record.Differ()) result.diff = DiffImage(runs[0].image, runs[1].image);
  }
  if (const BackendRun* judged = Judged(runs, options, record)) {
    Say(status, std::string("verifying the ") + judged->record.Name() + " image...");
    Judge(scene, list, *judged, options, result);
  }
  for (BackendRun& run : runs) {
    record.backends.push_back(run.record);
    result.images.push_back(std::move(run.image));
    result.drawn_by.push_back(std::move(run.drawn_by));
  }
  record.verdict = VerdictOf(record);
  return result;
}

}  // namespace twinraster::run
