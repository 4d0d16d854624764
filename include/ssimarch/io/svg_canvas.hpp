// The one SVG writer of the library: a document of rectangles, lines, polylines, circles and text,
// and a plot box that maps data coordinates to pixels. Used by the trace pictures (svg_plot.hpp)
// and the porosity profile plots (profile_plot.hpp). Numbers are written with the stream's current
// formatting, so a caller controls precision with the usual manipulators.
#pragma once

#include <ostream>
#include <span>
#include <string>
#include <string_view>

#include "ssimarch/core/vec3.hpp"

namespace ssimarch {

/// A data window [xmin, xmax] x [ymin, ymax] drawn in the pixel box (left, top, width, height);
/// x grows to the right, y upwards (SVG's y axis points down).
struct PlotBox {
  double left = 0, top = 0, width = 1, height = 1;
  double xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  double px(double x) const { return left + (x - xmin) / (xmax - xmin) * width; }
  double py(double y) const { return top + (ymax - y) / (ymax - ymin) * height; }
};

/// `s` with the five XML special characters escaped, for text and attribute values.
std::string xml_escape(std::string_view s);

/// Writes one SVG document to `out`. `style` arguments are raw attributes appended to an element
/// (e.g. "fill='none' stroke='#999'"), written as given.
class SvgCanvas {
 public:
  /// Writes the XML prolog, the <svg> element (with `attributes` after width and height) and a
  /// background rectangle filling the picture.
  SvgCanvas(std::ostream& out, int width, int height, std::string_view attributes, std::string_view background);
  SvgCanvas(const SvgCanvas&) = delete;
  SvgCanvas& operator=(const SvgCanvas&) = delete;

  std::ostream& stream() { return out_; }

  void rect(double x, double y, double width, double height, std::string_view style);
  void line(double x1, double y1, double x2, double y2, std::string_view style);
  void circle(double cx, double cy, double r, std::string_view style);
  /// A polyline through the points (x[i], y[i]) of the data window `box`; non-finite points skipped.
  template <class Xs, class Ys>
  void polyline(const PlotBox& box, const Xs& x, const Ys& y, std::string_view style);
  /// A polyline through points already in pixels.
  void polyline(std::span<const Vec2> points, std::string_view style);
  /// Opens <text x y style>; write the content to stream(), then call end_text().
  std::ostream& text(double x, double y, std::string_view style);
  /// Text turned by -90 degrees about its anchor (a vertical axis label).
  std::ostream& vertical_text(double x, double y, std::string_view style);
  void end_text();
  /// Closes the document (</svg>); the destructor does not.
  void finish();

 private:
  void polyline_start(std::string_view style);
  void polyline_point(const PlotBox& box, double x, double y);
  void polyline_end();
  std::ostream& out_;
};

template <class Xs, class Ys>
void SvgCanvas::polyline(const PlotBox& box, const Xs& x, const Ys& y, std::string_view style) {
  polyline_start(style);
  for (std::size_t i = 0; i < x.size() && i < y.size(); ++i) polyline_point(box, x[i], y[i]);
  polyline_end();
}

}  // namespace ssimarch
