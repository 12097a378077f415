// The bench's plots on their own: each point carries its numbers, log and linear axes.
#include "bench_report/svg_plot.hpp"

#include "support/catch.hpp"

#include <cstddef>
#include <string>

using namespace twinraster::bench_report;

namespace {

std::size_t Count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace

TEST_CASE("PlotSvg: each point carries its numbers, and on a log axis 0 sits on the floor", "[bench_report]") {
  Plot plot;
  plot.x = {"ms", true, std::nullopt};
  plot.y = {"error", true, 1e-9};
  plot.series = {{"<a&b>", "#123456", {{10, 0, "zero"}, {100, 1e-3, "some"}}, true}};
  const std::string svg = PlotSvg(plot);
  CHECK(Count(svg, "class=\"point\"") == 2);
  CHECK(svg.find("data-x=\"10\" data-y=\"0\"") != std::string::npos);
  CHECK(svg.find("data-x=\"100\" data-y=\"0.001\"") != std::string::npos);
  CHECK(svg.find("≤1e-9") != std::string::npos);
  CHECK(svg.find("&lt;a&amp;b&gt;") != std::string::npos);
  CHECK(svg.find("<a&b>") == std::string::npos);
  CHECK(svg.find("nan") == std::string::npos);
}

TEST_CASE("PlotSvg: a linear axis ticks round numbers and starts at 0 for positive data", "[bench_report]") {
  Plot plot;
  plot.x = {"instances", false, std::nullopt};
  plot.y = {"ms", false, std::nullopt};
  plot.series = {{"twin", "#000", {{1, 2, "one"}, {9, 40, "nine"}}, true}};
  const std::string svg = PlotSvg(plot);
  CHECK(svg.find(">0</text>") != std::string::npos);
  CHECK(svg.find(">10</text>") != std::string::npos);
  CHECK(svg.find("(log)") == std::string::npos);
  CHECK(svg.find("<polyline") != std::string::npos);
}
