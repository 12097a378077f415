#include "bench/bench_suite.hpp"

#include "base/stopwatch.hpp"
#include "base/usage_error.hpp"
#include "bench/error_metrics.hpp"
#include "bench/vertex_methods.hpp"
#include "chain/draw_list.hpp"
#include "cpu/cpu_renderer.hpp"
#include "gpu/gpu_renderer.hpp"
#include "image/image_compare.hpp"
#include "run/backend_draws.hpp"
#include "scene/scene_loader.hpp"
#include "truth/truth_renderer.hpp"
#include "twin_rules/twin_rules.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <string_view>
#include <thread>

namespace twinraster::bench {

namespace {

// Median of `runs` timings of fn() (which keeps its own last result).
double MedianMs(int runs, const std::function<void()>& fn) {
  std::vector<double> times;
  for (int i = 0; i < runs; ++i) {
    Stopwatch clock;
    fn();
    times.push_back(clock.Milliseconds());
  }
  std::sort(times.begin(), times.end());
  return times.size() % 2 ? times[times.size() / 2] : (times[times.size() / 2 - 1] + times[times.size() / 2]) / 2;
}

// Scenes with more instances are left out of the default suite.
constexpr std::size_t kSuiteMaxInstances = 100'000;

std::vector<std::filesystem::path> SuiteScenes(const BenchOptions& options) {
  std::vector<std::filesystem::path> files;
  for (const char* sub : {"", "hard", "bench"}) {
    const std::filesystem::path dir = options.scenes_dir / sub;
    if (!std::filesystem::is_directory(dir)) continue;
    std::vector<std::filesystem::path> here;
    for (const auto& entry : std::filesystem::directory_iterator(dir))
      if (entry.is_regular_file() && entry.path().extension() == ".json") here.push_back(entry.path());
    std::sort(here.begin(), here.end());
    files.insert(files.end(), here.begin(), here.end());
  }
  if (options.only) {
    std::erase_if(files, [&](const auto& f) { return f.string().find(*options.only) == std::string::npos; });
  } else {
    // The million cubes would take the truth minutes per run; `bench --scale` measures them, and
    // --only still picks them.
    std::erase_if(files, [](const auto& f) { return LoadScene(f).instances.size() > kSuiteMaxInstances; });
  }
  return files;
}

// The depth-precision scenes draw a blue plate behind a red one: blue where the truth shows red
// is depth failing to tell the plates apart.
std::optional<std::uint64_t> ZFighting(const std::filesystem::path& file, const Image& image, const Image& truth) {
  if (file.filename().string().find("depth-ratio") == std::string::npos) return std::nullopt;
  std::uint64_t count = 0;
  for (std::size_t i = 0; i < image.rgba.size(); i += 4) {
    const bool blue = image.rgba[i] == 0 && image.rgba[i + 2] == 255;
    const bool truth_red = truth.rgba[i] == 255 && truth.rgba[i + 2] == 0;
    count += (blue && truth_red) ? 1 : 0;
  }
  return count;
}

// lavapipe reads LP_NUM_THREADS when an instance creates its device: 0 rasterizes on its own
// queue thread (one thread in all), N > 0 starts N rasterizer threads. A renderer keeps the count
// it was created with, so the variable is set just for its construction.
gpu::GpuRenderer LavapipeWithThreads(unsigned threads) {
  const char* previous = std::getenv("LP_NUM_THREADS");
  const std::string saved = previous ? previous : "";
  ::setenv("LP_NUM_THREADS", threads <= 1 ? "0" : std::to_string(threads).c_str(), 1);
  gpu::GpuRenderer renderer;
  if (previous)
    ::setenv("LP_NUM_THREADS", saved.c_str(), 1);
  else
    ::unsetenv("LP_NUM_THREADS");
  return renderer;
}

}  // namespace

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

std::string MachineDescription(const std::string& device) {
  std::string model = "unknown CPU";
  std::ifstream cpuinfo("/proc/cpuinfo");
  for (std::string line; std::getline(cpuinfo, line);) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
  return model + ", " + std::to_string(std::thread::hardware_concurrency()) + " hardware threads; Vulkan: " + device;
}

std::vector<std::string> BenchMethodNames() {
  std::vector<std::string> names;
  for (VertexMethod m : kAllMethods) names.emplace_back(MethodName(m));
  names.emplace_back("cpu-twin");
  names.emplace_back("lavapipe");
  names.emplace_back("cpu-twin-swiftshader");
  names.emplace_back("swiftshader");
  return names;
}

namespace {

using Lavapipes = std::vector<std::pair<unsigned, std::optional<gpu::GpuRenderer>>>;

// One lavapipe per thread count the renderer rows use (one thread, every core), made only when
// those rows are asked for, so that the rest runs without Vulkan.
Lavapipes MakeLavapipes(unsigned cores, bool wanted) {
  Lavapipes lavapipes;
  for (unsigned threads : {1u, cores}) {
    if (!lavapipes.empty() && threads == lavapipes.front().first) break;
    lavapipes.emplace_back(threads, std::nullopt);
    if (wanted) lavapipes.back().second.emplace(LavapipeWithThreads(threads));
  }
  return lavapipes;
}

// What every row of a scene compares against: its draw list, the truth's image and, for lit or
// vertex-coloured scenes, which triangle the truth shows where.
struct SceneTruth {
  Scene scene;
  DrawList list;
  truth::ExactClipPositions exact;
  truth::TruthImage surfaces;
  std::optional<DrawList> surface_list;  // smooth scenes: the positions rasterized again with SurfaceList
};

SceneTruth MakeSceneTruth(const std::filesystem::path& file) {
  SceneTruth t;
  t.scene = LoadScene(file);
  t.scene.wireframe = false;  // the bench compares filled (and lit) images with the truth, whatever the scene asks
  t.list = BuildDrawList(t.scene);
  t.exact = truth::ExactClipSpace(t.scene);
  const truth::ExactLight light(t.scene);
  t.surfaces = truth::RenderTruthSurfaces(t.list, t.exact, &light);
  // Colours that vary across a triangle (light, vertex colours) are compared surface by surface.
  if (std::any_of(t.list.meshes.begin(), t.list.meshes.end(), [](const DrawMesh& m) { return m.smooth(); }))
    t.surface_list = SurfaceList(t.list);
  return t;
}

// The row's image against the truth: pixels, z-fighting and, on lit or vertex-coloured scenes, how
// far its colours are from the truth's, triangle by triangle (which triangle a pixel shows found
// with `rules`, the rules of the device that drew it).
void MeasureImage(BenchRow& row, const std::filesystem::path& file, const SceneTruth& t, const Image& image,
                  const cpu::ClipPositions* clip, unsigned cores, const cpu::RasterRules& rules = {}) {
  row.image_error_px = CompareImages(image, t.surfaces.image).differing_pixels;
  row.z_fighting_px = ZFighting(file, image, t.surfaces.image);
  if (!t.surface_list) return;
  const cpu::CpuOptions options{.threads = cores, .rules = rules};
  const Image surfaces =
      clip ? cpu::RasterizeClipSpace(*t.surface_list, *clip, options) : cpu::RenderOnCpu(*t.surface_list, options);
  const ColourError error = SameSurfaceColourError(image, surfaces, t.surfaces);
  row.colour_error = error.max_channel;
  row.colour_pixels = error.pixels;
}

BenchRow BaseRow(const std::filesystem::path& file, const BenchOptions& options, const DrawList& list) {
  BenchRow base;
  base.scene = std::filesystem::relative(file, options.scenes_dir).replace_extension().generic_string();
  base.width = list.width, base.height = list.height;
  for (const DrawCall& d : list.draws) {
    base.vertices += list.meshes[d.mesh].positions.size();
    base.triangles += list.meshes[d.mesh].triangles.size();
  }
  return base;
}

// A vertex method: its vertex stage alone, then a whole frame on the CPU twin's rasterizer.
BenchRow MethodRow(VertexMethod method, const BenchRow& base, const std::filesystem::path& file, const SceneTruth& t,
                   int runs, unsigned cores) {
  BenchRow row = base;
  row.method = std::string(MethodName(method));
  row.threads = cores;
  cpu::ClipPositions clip;
  row.vertex_ms = MedianMs(runs, [&] { clip = TransformVertices(t.scene, t.list, method); });
  row.vertex_error_px = VertexErrorPixels(clip, t.exact, t.list.width, t.list.height);
  Image image;
  row.frame_ms = MedianMs(runs, [&] {
    image = cpu::RasterizeClipSpace(t.list, TransformVertices(t.scene, t.list, method), cpu::CpuOptions{cores});
  });
  MeasureImage(row, file, t, image, &clip, cores);
  return row;
}

// A renderer as a user runs it: the twin with one device's rules (run/backend_draws.hpp, as
// `render` draws), or that device in this process, so that its frame time holds no child process.
struct Renderer {
  const char* method;
  cpu::RasterRules rules;              // the device's, which the twin follows
  gpu::GpuRenderer* device = nullptr;  // null: the twin draws
};

BenchRow RendererRow(const Renderer& renderer, unsigned threads, const BenchRow& base,
                     const std::filesystem::path& file, const SceneTruth& t, int runs, unsigned cores) {
  BenchRow row = base;
  row.method = renderer.method;
  row.threads = threads;
  Image image;
  row.frame_ms = MedianMs(runs, [&] {
    image = renderer.device ? renderer.device->Render(t.list) : run::DrawOnTwin(t.list, renderer.rules, threads).image;
  });
  MeasureImage(row, file, t, image, nullptr, cores, renderer.rules);  // the device covers what its twin covers
  return row;
}

}  // namespace

BenchResult RunBench(const BenchOptions& options) {
  Stopwatch total;
  BenchResult result;
  result.runs = options.runs;
  const auto selected = [&](std::string_view name) {
    return options.methods.empty() ||
           std::find(options.methods.begin(), options.methods.end(), name) != options.methods.end();
  };
  const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
  Lavapipes lavapipes = MakeLavapipes(cores, selected("lavapipe"));
  // SwiftShader runs on its own pool of one thread per core: its rows are at every core only.
  std::optional<gpu::GpuRenderer> swiftshader;
  if (selected("swiftshader")) swiftshader.emplace(gpu::GpuOptions{.device = "SwiftShader"});
  result.machine = MachineDescription(lavapipes.front().second ? lavapipes.front().second->DeviceName() : "not used");
  if (swiftshader) result.machine += " and " + swiftshader->DeviceName();

  const std::vector<std::filesystem::path> files = SuiteScenes(options);
  if (files.empty())
    throw UsageError("no scene in " + options.scenes_dir.string() +
                     (options.only ? " matches --only " + *options.only : ""));

  // Known before the first row is measured, so that progress can say "row 3 of 56".
  std::size_t rows_per_scene = 0;
  for (VertexMethod method : kAllMethods) rows_per_scene += selected(MethodName(method)) ? 1 : 0;
  for (const char* renderer : {"cpu-twin", "lavapipe"}) rows_per_scene += selected(renderer) ? lavapipes.size() : 0;
  for (const char* renderer : {"cpu-twin-swiftshader", "swiftshader"}) rows_per_scene += selected(renderer) ? 1 : 0;
  const std::size_t total_rows = rows_per_scene * files.size();
  const auto add_row = [&](const BenchRow& row) {
    result.rows.push_back(row);
    if (options.on_row) options.on_row(result.rows.back(), result.rows.size(), total_rows);
  };
  for (const std::filesystem::path& file : files) {
    const SceneTruth truth = MakeSceneTruth(file);
    const BenchRow base = BaseRow(file, options, truth.list);
    for (VertexMethod method : kAllMethods) {
      if (selected(MethodName(method))) add_row(MethodRow(method, base, file, truth, options.runs, cores));
    }
    // The twin and lavapipe with one thread and with every core, back to back; then the twin with
    // SwiftShader's rules and SwiftShader.
    for (auto& [threads, lavapipe] : lavapipes) {
      for (const Renderer& r : {Renderer{"cpu-twin", {}}, Renderer{"lavapipe", {}, lavapipe ? &*lavapipe : nullptr}}) {
        if (selected(r.method)) add_row(RendererRow(r, threads, base, file, truth, options.runs, cores));
      }
    }
    const cpu::RasterRules swiftshader_rules = twin_rules::SwiftShaderRow().rules;
    for (const Renderer& r : {Renderer{"cpu-twin-swiftshader", swiftshader_rules},
                              Renderer{"swiftshader", swiftshader_rules, swiftshader ? &*swiftshader : nullptr}}) {
      if (selected(r.method)) add_row(RendererRow(r, cores, base, file, truth, options.runs, cores));
    }
  }
  result.seconds = total.Milliseconds() / 1000;
  return result;
}

}  // namespace twinraster::bench
