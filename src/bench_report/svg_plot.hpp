// A scatter or line plot as inline SVG, on linear or log axes: the one way every page plots.
// Each point carries its numbers (data-x, data-y, a tooltip), so a reader can hover and a test
// can check them against the --json output they came from.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace twinraster::bench_report {

struct PlotPoint {
  double x = 0, y = 0;
  std::string label;  // the tooltip: which scene or size this is
};

struct PlotSeries {
  std::string name;    // the legend's entry
  std::string colour;  // any SVG colour
  std::vector<PlotPoint> points;
  bool joined = false;  // a line through the points in their order, not just the points
};

struct PlotAxis {
  std::string label;
  bool log = true;
  // Log axes: values at or below `floor` are drawn on it, and its tick says "≤" (an error of 0).
  std::optional<double> floor;
};

struct ReferenceLine {  // a dashed horizontal line, such as 1/256 px
  double y = 0;
  std::string label;
};

struct Plot {
  std::string title;  // drawn above the plot; may be empty
  PlotAxis x, y;
  std::vector<PlotSeries> series;
  std::vector<ReferenceLine> references;
  double width = 640, height = 400;
};

// A standalone <svg> element (with xmlns), usable inline in HTML or as an .svg file.
std::string PlotSvg(const Plot& plot);

}  // namespace twinraster::bench_report
