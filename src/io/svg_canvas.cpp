// The SVG writer (see svg_canvas.hpp). Attributes use single quotes throughout.
#include "ssimarch/io/svg_canvas.hpp"

#include <cmath>

namespace ssimarch {

std::string xml_escape(std::string_view s) {
  std::string o;
  o.reserve(s.size());
  for (char c : s) {
    switch (c) {
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '&': o += "&amp;"; break;
      case '"': o += "&quot;"; break;
      case '\'': o += "&apos;"; break;
      default: o += c;
    }
  }
  return o;
}

SvgCanvas::SvgCanvas(std::ostream& out, int width, int height, std::string_view attributes,
                     std::string_view background)
    : out_(out) {
  out_ << "<?xml version='1.0' encoding='UTF-8'?>\n<svg xmlns='http://www.w3.org/2000/svg' width='" << width
       << "' height='" << height << "'" << (attributes.empty() ? "" : " ") << attributes
       << ">\n<rect width='100%' height='100%' fill='" << background << "'/>\n";
}

void SvgCanvas::rect(double x, double y, double width, double height, std::string_view style) {
  out_ << "<rect x='" << x << "' y='" << y << "' width='" << width << "' height='" << height << "' " << style
       << "/>\n";
}

void SvgCanvas::line(double x1, double y1, double x2, double y2, std::string_view style) {
  out_ << "<line x1='" << x1 << "' y1='" << y1 << "' x2='" << x2 << "' y2='" << y2 << "' " << style << "/>\n";
}

void SvgCanvas::circle(double cx, double cy, double r, std::string_view style) {
  out_ << "<circle cx='" << cx << "' cy='" << cy << "' r='" << r << "' " << style << "/>\n";
}

std::ostream& SvgCanvas::text(double x, double y, std::string_view style) {
  out_ << "<text x='" << x << "' y='" << y << "'" << (style.empty() ? "" : " ") << style << ">";
  return out_;
}

std::ostream& SvgCanvas::vertical_text(double x, double y, std::string_view style) {
  out_ << "<text x='" << x << "' y='" << y << "' " << style << " transform='rotate(-90 " << x << " " << y << ")'>";
  return out_;
}

void SvgCanvas::end_text() { out_ << "</text>\n"; }

void SvgCanvas::finish() { out_ << "</svg>\n"; }

void SvgCanvas::polyline_start(std::string_view style) { out_ << "<polyline " << style << " points='"; }

void SvgCanvas::polyline_point(const PlotBox& box, double x, double y) {
  if (std::isfinite(x) && std::isfinite(y)) out_ << box.px(x) << "," << box.py(y) << " ";
}

void SvgCanvas::polyline(std::span<const Vec2> points, std::string_view style) {
  polyline_start(style);
  for (const Vec2& q : points) out_ << q.x() << "," << q.y() << " ";
  polyline_end();
}

void SvgCanvas::polyline_end() { out_ << "'/>\n"; }

}  // namespace ssimarch
