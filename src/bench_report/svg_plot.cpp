#include "bench_report/svg_plot.hpp"

#include "markup/markup.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace twinraster::bench_report {

namespace {

// Where an axis's values go, in pixels, and its ticks.
struct Scale {
  bool log = true;
  double lo = 0, hi = 1;  // in axis units: log10 of the value on a log axis
  double from = 0, to = 1;
  std::optional<double> floor;

  double Value(double v) const {
    if (!log) return v;
    if (floor && v <= *floor) v = *floor;
    return std::log10(std::max(v, 1e-300));
  }
  double At(double v) const { return from + (Value(v) - lo) / (hi - lo) * (to - from); }
};

Scale MakeScale(const PlotAxis& axis, const std::vector<double>& values, double from, double to) {
  Scale s{axis.log, 0, 1, from, to, axis.floor};
  double lo = 1e300, hi = -1e300;
  for (const double v : values) {
    if (!std::isfinite(v) || (axis.log && !axis.floor && v <= 0)) continue;
    lo = std::min(lo, s.Value(v)), hi = std::max(hi, s.Value(v));
  }
  if (lo > hi) lo = 0, hi = 1;
  if (axis.log) {
    lo = std::floor(lo + 1e-9), hi = std::ceil(hi - 1e-9);  // a value on a decade ends the axis there
    if (hi <= lo) hi = lo + 1;
  } else {
    if (axis.floor) lo = std::min(lo, *axis.floor);
    const double span = hi > lo ? hi - lo : std::max(1.0, std::abs(hi));
    // Positive data no further from 0 than their own spread start at 0, so that sizes compare.
    lo = lo >= 0 && lo <= span ? 0 : lo - 0.05 * span, hi += 0.05 * span;
  }
  s.lo = lo, s.hi = hi;
  return s;
}

// Tick values (in axis units) and their labels.
std::vector<std::pair<double, std::string>> Ticks(const Scale& s) {
  std::vector<std::pair<double, std::string>> ticks;
  if (s.log) {
    const double step = std::max(1.0, std::ceil((s.hi - s.lo) / 8));
    for (double e = s.lo; e <= s.hi + 1e-9; e += step) {
      const bool is_floor = s.floor && std::abs(e - std::log10(*s.floor)) < 1e-9;
      ticks.emplace_back(e, (is_floor ? "≤1e" : "1e") + markup::Number(e, 3));
    }
  } else {
    const double raw = (s.hi - s.lo) / 6;
    const double magnitude = std::pow(10, std::floor(std::log10(raw)));
    const double step = raw / magnitude < 2 ? 2 * magnitude : raw / magnitude < 5 ? 5 * magnitude : 10 * magnitude;
    for (double v = std::ceil(s.lo / step) * step; v <= s.hi + 1e-9 * step; v += step)
      ticks.emplace_back(v, markup::Number(v, 4));
  }
  return ticks;
}

}  // namespace

std::string PlotSvg(const Plot& plot) {
  const double legend_width = 170, left = 70, top = plot.title.empty() ? 16 : 34, bottom = 52;
  const double right = plot.width - legend_width;
  std::vector<double> xs, ys;
  for (const PlotSeries& s : plot.series) {
    for (const PlotPoint& p : s.points) xs.push_back(p.x), ys.push_back(p.y);
  }
  for (const ReferenceLine& r : plot.references) ys.push_back(r.y);
  const Scale sx = MakeScale(plot.x, xs, left, right);
  const Scale sy = MakeScale(plot.y, ys, plot.height - bottom, top);
  const auto x_at = [&](double v) { return markup::Number(sx.At(v), 6); };
  const auto y_at = [&](double v) { return markup::Number(sy.At(v), 6); };

  std::ostringstream svg;
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << plot.width << "\" height=\"" << plot.height
      << "\" viewBox=\"0 0 " << plot.width << " " << plot.height
      << "\" font-family=\"sans-serif\" font-size=\"11\" role=\"img\" class=\"plot\">\n"
      << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  if (!plot.title.empty()) {
    svg << "<text x=\"" << left << "\" y=\"18\" font-size=\"13\" font-weight=\"bold\">" << markup::Escape(plot.title)
        << "</text>\n";
  }
  for (const auto& [v, label] : Ticks(sx)) {
    const double x = sx.from + (v - sx.lo) / (sx.hi - sx.lo) * (sx.to - sx.from);
    svg << "<line x1=\"" << markup::Number(x, 6) << "\" y1=\"" << top << "\" x2=\"" << markup::Number(x, 6)
        << "\" y2=\"" << plot.height - bottom << "\" stroke=\"#e2e2e2\"/><text x=\"" << markup::Number(x, 6)
        << "\" y=\"" << plot.height - bottom + 14 << "\" text-anchor=\"middle\">" << markup::Escape(label)
        << "</text>\n";
  }
  for (const auto& [v, label] : Ticks(sy)) {
    const double y = sy.from + (v - sy.lo) / (sy.hi - sy.lo) * (sy.to - sy.from);
    svg << "<line x1=\"" << left << "\" y1=\"" << markup::Number(y, 6) << "\" x2=\"" << right << "\" y2=\""
        << markup::Number(y, 6) << "\" stroke=\"#e2e2e2\"/><text x=\"" << left - 5 << "\" y=\""
        << markup::Number(y + 4, 6) << "\" text-anchor=\"end\">" << markup::Escape(label) << "</text>\n";
  }
  svg << "<rect x=\"" << left << "\" y=\"" << top << "\" width=\"" << right - left << "\" height=\""
      << plot.height - bottom - top << "\" fill=\"none\" stroke=\"#999\"/>\n";
  svg << "<text x=\"" << (left + right) / 2 << "\" y=\"" << plot.height - 16 << "\" text-anchor=\"middle\">"
      << markup::Escape(plot.x.label) << (plot.x.log ? " (log)" : "") << "</text>\n";
  const double mid = (top + plot.height - bottom) / 2;
  svg << "<text transform=\"translate(14 " << mid << ") rotate(-90)\" text-anchor=\"middle\">"
      << markup::Escape(plot.y.label) << (plot.y.log ? " (log)" : "") << "</text>\n";
  for (const ReferenceLine& r : plot.references) {
    svg << "<line x1=\"" << left << "\" y1=\"" << y_at(r.y) << "\" x2=\"" << right << "\" y2=\"" << y_at(r.y)
        << "\" stroke=\"#777\" stroke-dasharray=\"4 3\"/><text x=\"" << right - 4 << "\" y=\""
        << markup::Number(sy.At(r.y) - 4, 6) << "\" text-anchor=\"end\" fill=\"#555\">" << markup::Escape(r.label)
        << "</text>\n";
  }
  double legend_y = top + 8;
  for (const PlotSeries& s : plot.series) {
    const std::string colour = markup::Escape(s.colour);
    svg << "<g class=\"series\" data-series=\"" << markup::Escape(s.name) << "\">\n";
    if (s.joined && s.points.size() > 1) {
      svg << "<polyline fill=\"none\" stroke-width=\"2\" stroke=\"" << colour << "\" points=\"";
      for (const PlotPoint& p : s.points) svg << x_at(p.x) << "," << y_at(p.y) << " ";
      svg << "\"/>\n";
    }
    for (const PlotPoint& p : s.points) {
      svg << "<circle class=\"point\" cx=\"" << x_at(p.x) << "\" cy=\"" << y_at(p.y)
          << "\" r=\"4\" fill-opacity=\"0.75\" fill=\"" << colour << "\" data-x=\"" << markup::Number(p.x, 17)
          << "\" data-y=\"" << markup::Number(p.y, 17) << "\"><title>"
          << markup::Escape(s.name + (p.label.empty() ? "" : ", " + p.label) + ": " + plot.x.label + " " +
                            markup::Number(p.x) + ", " + plot.y.label + " " + markup::Number(p.y))
          << "</title></circle>\n";
    }
    svg << "</g>\n<circle cx=\"" << right + 16 << "\" cy=\"" << legend_y << "\" r=\"5\" fill=\"" << colour
        << "\"/><text x=\"" << right + 26 << "\" y=\"" << legend_y + 4 << "\">" << markup::Escape(s.name)
        << "</text>\n";
    legend_y += 18;
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace twinraster::bench_report
