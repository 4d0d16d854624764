// Line plots of profiles: SVG written directly, PNG through /usr/bin/python3 with matplotlib.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace ssimarch::porosity {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::string color = "#1f77b4";
  bool dashed = false;
};

struct PlotSpec {
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
};

/// Writes an SVG line plot. Throws std::runtime_error if the file cannot be written.
void write_svg_plot(const std::filesystem::path& path, const PlotSpec& spec);
/// Writes a PNG with matplotlib (/usr/bin/python3). Throws std::runtime_error with the reason if
/// python3 or matplotlib is unavailable or the plot fails.
void write_png_plot(const std::filesystem::path& path, const PlotSpec& spec);
/// Chooses SVG or PNG by the file extension (.svg / .png); other extensions are an error.
void write_plot(const std::filesystem::path& path, const PlotSpec& spec);

}  // namespace ssimarch::porosity
