// Line plots of porosity profiles (a profile, and e.g. a correlation curve to compare with) as SVG:
// axes with 1-2-5 ticks, grid, title, axis labels and a legend. Drawn with SvgCanvas, the writer of
// the trace pictures too.
#pragma once

#include <filesystem>
#include <ostream>
#include <string>
#include <vector>

namespace ssimarch {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::string color = "#1f77b4";
  bool dashed = false;
};

struct ProfilePlot {
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
};

/// Writes the plot as an SVG document. The y range always includes [0, 1] (porosities).
void write_profile_plot(std::ostream& out, const ProfilePlot& plot);
/// Writes the plot to an .svg file, all or nothing (io/output_files.hpp). Throws InputError if the
/// name does not end in .svg, OutputError if the file cannot be written.
void write_profile_plot(const std::filesystem::path& path, const ProfilePlot& plot);

/// The staircase of a bin profile (value k held on [lower[k], upper[k]]) as a polyline.
PlotSeries staircase(std::string label, const std::vector<double>& lower, const std::vector<double>& upper,
                     const std::vector<double>& values);

}  // namespace ssimarch
