// Profile plots (see profile_plot.hpp).
#include "ssimarch/io/profile_plot.hpp"
#include "ssimarch/io/output_files.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/svg_canvas.hpp"

namespace ssimarch {

namespace {

constexpr int kWidth = 800, kHeight = 500;
constexpr double kLeft = 80, kRight = 30, kTop = 40, kBottom = 60;  // margins, pixels

// "Nice" tick step for a range: 1, 2 or 5 times a power of ten, about `target` ticks.
double tick_step(double span, int target) {
  const double raw = span / std::max(1, target);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string tick_label(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", std::abs(v) < 1e-12 ? 0.0 : v);
  return b;
}

// The data window: every finite point, with y stretched to contain [0, 1].
PlotBox data_box(const ProfilePlot& plot) {
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& s : plot.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]);
      x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]);
      y1 = std::max(y1, s.y[i]);
    }
  if (!(x1 > x0)) x0 = 0, x1 = 1;
  if (!(y1 > y0)) y0 = 0, y1 = 1;
  return {kLeft, kTop, kWidth - kLeft - kRight, kHeight - kTop - kBottom, x0, x1, std::min(y0, 0.0), std::max(y1, 1.0)};
}

void draw_axes(SvgCanvas& svg, const PlotBox& b, const ProfilePlot& plot) {
  const double xs = tick_step(b.xmax - b.xmin, 8), ys = tick_step(b.ymax - b.ymin, 6);
  const double bottom = b.top + b.height, right = b.left + b.width;
  for (double t = std::ceil(b.xmin / xs) * xs; t <= b.xmax + 1e-9 * xs; t += xs) {
    svg.line(b.px(t), b.top, b.px(t), bottom, "stroke='#e0e0e0'");
    svg.text(b.px(t), bottom + 18, "text-anchor='middle'") << tick_label(t);
    svg.end_text();
  }
  for (double t = std::ceil(b.ymin / ys) * ys; t <= b.ymax + 1e-9 * ys; t += ys) {
    svg.line(b.left, b.py(t), right, b.py(t), "stroke='#e0e0e0'");
    svg.text(b.left - 8, b.py(t) + 4, "text-anchor='end'") << tick_label(t);
    svg.end_text();
  }
  svg.rect(b.left, b.top, b.width, b.height, "fill='none' stroke='black'");
  svg.text(kWidth / 2.0, 24, "text-anchor='middle' font-size='16'") << xml_escape(plot.title);
  svg.end_text();
  svg.text(b.left + b.width / 2, kHeight - 18, "text-anchor='middle'") << xml_escape(plot.xlabel);
  svg.end_text();
  svg.vertical_text(22, b.top + b.height / 2, "text-anchor='middle'") << xml_escape(plot.ylabel);
  svg.end_text();
}

void draw_series(SvgCanvas& svg, const PlotBox& b, const ProfilePlot& plot) {
  int k = 0;
  for (const auto& s : plot.series) {
    const std::string dash = s.dashed ? " stroke-dasharray='6,4'" : "";
    svg.polyline(b, s.x, s.y, "fill='none' stroke='" + xml_escape(s.color) + "' stroke-width='1.6'" + dash);
    const double ly = b.top + 20 + 18 * k++;  // legend, top right
    const double lx = b.left + b.width;
    svg.line(lx - 330, ly, lx - 300, ly, "stroke='" + xml_escape(s.color) + "' stroke-width='2'" + dash);
    svg.text(lx - 294, ly + 4, "") << xml_escape(s.label);
    svg.end_text();
  }
}

}  // namespace

void write_profile_plot(std::ostream& out, const ProfilePlot& plot) {
  const PlotBox box = data_box(plot);
  SvgCanvas svg(out, kWidth, kHeight, "font-family='sans-serif' font-size='13'", "white");
  draw_axes(svg, box, plot);
  draw_series(svg, box, plot);
  svg.finish();
}

void write_profile_plot(const std::filesystem::path& path, const ProfilePlot& plot) {
  if (path.extension() != ".svg") throw InputError(path.string(), "a plot file must end in .svg");
  OutputFiles files;
  write_profile_plot(files.open(path), plot);
  files.commit();
}

PlotSeries staircase(std::string label, const std::vector<double>& lower, const std::vector<double>& upper,
                     const std::vector<double>& values) {
  PlotSeries s;
  s.label = std::move(label);
  for (std::size_t k = 0; k < values.size() && k < lower.size() && k < upper.size(); ++k) {
    s.x.insert(s.x.end(), {lower[k], upper[k]});
    s.y.insert(s.y.end(), {values[k], values[k]});
  }
  return s;
}

}  // namespace ssimarch
