#include "bench_report/bench_pages.hpp"

#include "base/counted.hpp"
#include "bench_report/svg_plot.hpp"
#include "markup/markup.hpp"

#include <map>
#include <sstream>

namespace twinraster::bench_report {

namespace {

// One colour per row kind, the same on every plot.
const std::map<std::string, std::string>& MethodColours() {
  static const std::map<std::string, std::string> colours = {
      {"compose-f64", "#1f77b4"},          {"compose-f32", "#d62728"}, {"steps-f32", "#ff7f0e"},
      {"camera-relative", "#2ca02c"},      {"cpu-twin", "#9467bd"},    {"lavapipe", "#8c564b"},
      {"cpu-twin-swiftshader", "#17becf"}, {"swiftshader", "#bcbd22"}};
  return colours;
}

std::string ColourOf(const std::string& method) {
  const auto found = MethodColours().find(method);
  return found == MethodColours().end() ? "#7f7f7f" : found->second;
}

// A row's name in a series: frame rows differ by thread count.
std::string SeriesName(const bench::BenchRow& r) {
  return r.vertex_ms >= 0 ? r.method : r.method + ", " + Counted(r.threads, "thread");
}

// An error of exactly 0 has no place on a log axis: it is drawn at the floor, marked "≤".
constexpr double kVertexErrorFloor = 1e-9;
constexpr double kPixelFloor = 0.5;

PlotSeries& SeriesFor(std::vector<PlotSeries>& series, const std::string& name, const std::string& colour) {
  for (PlotSeries& s : series) {
    if (s.name == name) return s;
  }
  series.push_back({name, colour, {}, false});
  return series.back();
}

std::string Section(const std::string& title, const std::string& body) {
  return "<h2>" + markup::Escape(title) + "</h2>\n" + body;
}

}  // namespace

std::string BenchChartSvg(const bench::BenchResult& result) {
  Plot plot;
  plot.title = "Vertex stage: time against error, every scene";
  plot.x = {"ms per million vertices (median)", true, std::nullopt};
  plot.y = {"max vertex error, px", true, kVertexErrorFloor};
  plot.references = {{1.0 / 256, "1/256 px"}};
  plot.width = 760, plot.height = 460;
  for (const bench::BenchRow& r : result.rows) {
    if (r.vertex_ms < 0 || r.vertex_error_px < 0 || r.vertices == 0) continue;
    std::string label = r.scene;
    if (r.colour_error) label += ", colour error " + std::to_string(*r.colour_error);
    SeriesFor(plot.series, r.method, ColourOf(r.method))
        .points.push_back({r.vertex_ms * 1e6 / double(r.vertices), r.vertex_error_px, label});
  }
  return PlotSvg(plot);
}

std::string BenchPageHtml(const bench::BenchResult& result, const std::string& table) {
  std::ostringstream page;
  page << markup::PageStart("twinraster bench") << "<h1>twinraster bench</h1>\n<p>" << markup::Escape(result.machine)
       << "; medians of " << Counted(result.runs, "run") << ", " << markup::Number(result.seconds, 3)
       << " s in all.</p>\n";
  page << Section(
      "Speed against error",
      "<p>Each way of computing the chain (compose-f64: F composed in double and rounded once; compose-f32: "
      "composed in float; steps-f32: the chapter's steps one at a time in float; camera-relative: the camera's "
      "translation taken out first), on every scene: time per million vertices against the largest distance "
      "from the truth's vertex positions. Lower left is better; an error of 0 sits on the bottom line.</p>\n");
  page << "<figure id=\"vertex-chart\">" << BenchChartSvg(result) << "</figure>\n";
  page << Section("Whole frames, scene by scene",
                  "<p>Per scene: each row's whole-frame time against the pixels where its image differs from the "
                  "truth's (log axes; 0 px on the bottom line).</p>\n");
  std::vector<std::string> scenes;
  for (const bench::BenchRow& r : result.rows) {
    if (scenes.empty() || scenes.back() != r.scene) scenes.push_back(r.scene);
  }
  for (const std::string& scene : scenes) {
    Plot plot;
    plot.title = scene;
    plot.x = {"frame ms (median)", true, std::nullopt};
    plot.y = {"px differing from the truth", true, kPixelFloor};
    plot.width = 520, plot.height = 300;
    for (const bench::BenchRow& r : result.rows) {
      if (r.scene != scene) continue;
      SeriesFor(plot.series, SeriesName(r), ColourOf(r.method))
          .points.push_back({r.frame_ms, static_cast<double>(r.image_error_px), scene});
    }
    page << "<figure class=\"scene-chart\" data-scene=\"" << markup::Escape(scene) << "\">" << PlotSvg(plot)
         << "</figure>\n";
  }
  page << Section("The table", "<pre>" + markup::Escape(table) + "</pre>\n") << markup::kPageEnd;
  return page.str();
}

std::string ScaleChartSvg(const bench::ScaleResult& result) {
  Plot plot;
  plot.title = "Cost against instance count";
  plot.x = {"instances", true, std::nullopt};
  plot.y = {"ms (median)", true, std::nullopt};
  plot.width = 700, plot.height = 420;
  PlotSeries gpu{"lavapipe, instanced", "#8c564b", {}, true}, pushed{"lavapipe, F per draw", "#e377c2", {}, true};
  PlotSeries twin{"CPU twin", "#9467bd", {}, true}, judge{"verifier", "#17becf", {}, true};
  for (const bench::ScaleRow& r : result.rows) {
    const double n = static_cast<double>(r.instances);
    const std::string label = Counted(r.instances, "instance");
    gpu.points.push_back({n, r.gpu_setup_ms + r.gpu_draw_ms, label});
    pushed.points.push_back({n, r.gpu_per_draw_ms, label});
    twin.points.push_back({n, r.twin_setup_ms + r.twin_draw_ms, label});
    judge.points.push_back({n, r.verify_ms, label});
  }
  plot.series = {gpu, pushed, twin, judge};
  return PlotSvg(plot);
}

std::string ScaleStagesSvg(const bench::ScaleResult& result) {
  Plot plot;
  plot.title = "Every stage against instance count";
  plot.x = {"instances", true, std::nullopt};
  plot.y = {"ms (median)", true, 1e-3};
  plot.width = 700, plot.height = 420;
  struct Stage {
    const char* name;
    const char* colour;
    double bench::ScaleRow::*value;
  };
  const Stage stages[] = {{"load", "#1f77b4", &bench::ScaleRow::load_ms},
                          {"host chain", "#ff7f0e", &bench::ScaleRow::chain_ms},
                          {"gpu set-up", "#2ca02c", &bench::ScaleRow::gpu_setup_ms},
                          {"gpu draw", "#8c564b", &bench::ScaleRow::gpu_draw_ms},
                          {"twin set-up", "#7f7f7f", &bench::ScaleRow::twin_setup_ms},
                          {"twin draw", "#9467bd", &bench::ScaleRow::twin_draw_ms},
                          {"png", "#bcbd22", &bench::ScaleRow::png_ms}};
  for (const Stage& stage : stages) {
    PlotSeries s{stage.name, stage.colour, {}, true};
    for (const bench::ScaleRow& r : result.rows) {
      s.points.push_back({static_cast<double>(r.instances), r.*stage.value, Counted(r.instances, "instance")});
    }
    plot.series.push_back(std::move(s));
  }
  return PlotSvg(plot);
}

std::string ScalePageHtml(const bench::ScaleResult& result, const std::string& table) {
  std::ostringstream page;
  page << markup::PageStart("twinraster bench --scale") << "<h1>twinraster bench --scale</h1>\n<p>"
       << markup::Escape(result.machine) << "; cubes written out one instance each; medians of "
       << Counted(result.runs, "run") << ".</p>\n";
  page << Section("Lavapipe, the twin and the verifier",
                  "<p>Drawing a frame on lavapipe (F in an instance buffer, or pushed per draw as in Listing 10-5), on "
                  "the CPU twin, and judging the twin's image with the verifier.</p>\n");
  page << "<figure id=\"scale-chart\">" << ScaleChartSvg(result) << "</figure>\n";
  page << "<figure id=\"stages-chart\">" << ScaleStagesSvg(result) << "</figure>\n";
  page << Section("The table", "<pre>" + markup::Escape(table) + "</pre>\n") << markup::kPageEnd;
  return page.str();
}

}  // namespace twinraster::bench_report
