// The SVG writer and the profile plot: exact element text, the data-to-pixel map, and a plot that
// holds its profile, its comparison curve, axes, labels and legend.
#include "ssimarch/io/profile_plot.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/io/output_files.hpp"
#include "ssimarch/io/svg_canvas.hpp"

namespace ssimarch {
namespace {

std::size_t count(const std::string& s, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t p = s.find(what); p != std::string::npos; p = s.find(what, p + 1)) ++n;
  return n;
}

TEST(io_SvgCanvas, WritesExactElements) {
  std::ostringstream o;
  SvgCanvas svg(o, 200, 100, "font-family='sans-serif'", "#fafafa");
  svg.rect(1, 2, 3, 4, "fill='none'");
  const PlotBox box{10, 20, 100, 50, 0, 2, -1, 1};  // x: 0..2 -> 10..110, y: 1..-1 -> 20..70
  const std::vector<double> x{0, 1, NAN, 2}, y{-1, 0, 0, 1};
  svg.polyline(box, x, y, "stroke='red'");
  svg.vertical_text(5, 6, "font-size='12'") << xml_escape("a<b & 'c'");
  svg.end_text();
  svg.finish();
  EXPECT_EQ(o.str(),
            "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='200' "
            "height='100' font-family='sans-serif'>\n<rect width='100%' height='100%' fill='#fafafa'/>\n"
            "<rect x='1' y='2' width='3' height='4' fill='none'/>\n"
            "<polyline stroke='red' points='10,70 60,45 110,20 '/>\n"
            "<text x='5' y='6' font-size='12' transform='rotate(-90 5 6)'>a&lt;b &amp; &apos;c&apos;</text>\n"
            "</svg>\n");
}

TEST(io_ProfilePlot, HoldsProfileCorrelationAxesAndLabels) {
  ProfilePlot plot;
  plot.title = "Radial porosity & correlation";
  plot.xlabel = "distance from the wall (R - r)/d";
  plot.ylabel = "porosity";
  PlotSeries exact{"exact", {0, 0.5, 1, 1.5, 2}, {1, 0.3, 0.5, 0.4, 0.42}, "#1f77b4", false};
  PlotSeries corr{"de Klerk (2003) correlation", {0, 1, 2}, {1, 0.45, 0.41}, "#d62728", true};
  plot.series = {exact, corr};
  std::ostringstream o;
  write_profile_plot(o, plot);
  const std::string s = o.str();
  EXPECT_EQ(s.rfind("<?xml", 0), 0u);
  EXPECT_EQ(s.substr(s.size() - 7), "</svg>\n");
  EXPECT_NE(s.find(">Radial porosity &amp; correlation</text>"), std::string::npos);
  EXPECT_NE(s.find(">distance from the wall (R - r)/d</text>"), std::string::npos);
  EXPECT_NE(s.find("rotate(-90"), std::string::npos);  // the vertical y label
  EXPECT_NE(s.find(">exact</text>"), std::string::npos);
  EXPECT_NE(s.find(">de Klerk (2003) correlation</text>"), std::string::npos);
  EXPECT_EQ(count(s, "<polyline"), 2u);
  EXPECT_EQ(count(s, "stroke-dasharray"), 2u);  // the dashed curve and its legend line
  // Ticks: y always spans [0, 1]; x ticks at 0, 0.5, ..., 2.
  for (const char* tick : {">0</text>", ">0.2</text>", ">1</text>", ">1.5</text>", ">2</text>"})
    EXPECT_NE(s.find(tick), std::string::npos) << tick;
  // The profile's five points, all inside the plot frame (80..770 x 40..440 pixels).
  const std::size_t a = s.find("points='") + 8, b = s.find('\'', a);
  std::istringstream pts(s.substr(a, b - a));
  int n = 0;
  for (double px, py; pts >> px && pts.ignore(1) && pts >> py; ++n) {
    EXPECT_GE(px, 80 - 1e-9);
    EXPECT_LE(px, 770 + 1e-9);
    EXPECT_GE(py, 40 - 1e-9);
    EXPECT_LE(py, 440 + 1e-9);
  }
  EXPECT_EQ(n, 5);
}

TEST(io_ProfilePlot, StaircaseAndFileErrors) {
  const PlotSeries st = staircase("bins", {0, 1}, {1, 2}, {0.3, 0.6});
  EXPECT_EQ(st.x, (std::vector<double>{0, 1, 1, 2}));
  EXPECT_EQ(st.y, (std::vector<double>{0.3, 0.3, 0.6, 0.6}));
  try {
    write_profile_plot(std::filesystem::path("plot.png"), ProfilePlot{});
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where(), "plot.png");
  }
  // A file that cannot be written is an OutputError (io/output_files.hpp), not bad input.
  EXPECT_THROW(write_profile_plot(std::filesystem::path("/nonexistent/dir/plot.svg"), ProfilePlot{}), OutputError);
}

}  // namespace
}  // namespace ssimarch
