// Plot writers. SVG: hand-written, no dependencies. PNG: a generated matplotlib script.
#include "ssimarch/porosity/plot.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace ssimarch::porosity {

namespace {

std::string xml_escape(const std::string& s) {
  std::string o;
  for (char c : s) {
    switch (c) {
      case '<': o += "&lt;"; break;
      case '>': o += "&gt;"; break;
      case '&': o += "&amp;"; break;
      case '"': o += "&quot;"; break;
      default: o += c;
    }
  }
  return o;
}

// "Nice" tick step for a range (1, 2 or 5 times a power of ten).
double tick_step(double span, int target) {
  const double raw = span / std::max(1, target);
  const double p = std::pow(10.0, std::floor(std::log10(raw)));
  for (double m : {1.0, 2.0, 5.0, 10.0})
    if (m * p >= raw) return m * p;
  return 10 * p;
}

std::string fmt(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", std::abs(v) < 1e-12 ? 0.0 : v);
  return b;
}

std::string py_list(const std::vector<double>& v) {
  std::ostringstream o;
  o.precision(17);
  o << "[";
  for (std::size_t i = 0; i < v.size(); ++i) o << (i ? "," : "") << v[i];
  o << "]";
  return o.str();
}

std::string py_str(const std::string& s) {
  std::string o = "\"";
  for (char c : s) {
    if (c == '"' || c == '\\') o += '\\';
    o += c;
  }
  return o + "\"";
}

}  // namespace

void write_svg_plot(const std::filesystem::path& path, const PlotSpec& spec) {
  double x0 = INFINITY, x1 = -INFINITY, y0 = INFINITY, y1 = -INFINITY;
  for (const auto& s : spec.series)
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i) {
      if (!std::isfinite(s.x[i]) || !std::isfinite(s.y[i])) continue;
      x0 = std::min(x0, s.x[i]); x1 = std::max(x1, s.x[i]);
      y0 = std::min(y0, s.y[i]); y1 = std::max(y1, s.y[i]);
    }
  if (!(x1 > x0)) { x0 = 0; x1 = 1; }
  if (!(y1 > y0)) { y0 = 0; y1 = 1; }
  y0 = std::min(y0, 0.0);
  y1 = std::max(y1, 1.0);
  const double W = 800, H = 500, L = 80, Rm = 30, T = 40, B = 60;
  auto X = [&](double x) { return L + (x - x0) / (x1 - x0) * (W - L - Rm); };
  auto Y = [&](double y) { return H - B - (y - y0) / (y1 - y0) * (H - T - B); };
  std::ofstream o(path);
  if (!o) throw std::runtime_error(path.string() + ": cannot write plot");
  o << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
    << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << W << "\" height=\"" << H << "\" viewBox=\"0 0 " << W
    << " " << H << "\" font-family=\"sans-serif\" font-size=\"13\">\n"
    << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  const double xs = tick_step(x1 - x0, 8), ys = tick_step(y1 - y0, 6);
  for (double t = std::ceil(x0 / xs) * xs; t <= x1 + 1e-9 * xs; t += xs)
    o << "<line x1=\"" << X(t) << "\" y1=\"" << T << "\" x2=\"" << X(t) << "\" y2=\"" << H - B
      << "\" stroke=\"#e0e0e0\"/><text x=\"" << X(t) << "\" y=\"" << H - B + 18 << "\" text-anchor=\"middle\">"
      << fmt(t) << "</text>\n";
  for (double t = std::ceil(y0 / ys) * ys; t <= y1 + 1e-9 * ys; t += ys)
    o << "<line x1=\"" << L << "\" y1=\"" << Y(t) << "\" x2=\"" << W - Rm << "\" y2=\"" << Y(t)
      << "\" stroke=\"#e0e0e0\"/><text x=\"" << L - 8 << "\" y=\"" << Y(t) + 4 << "\" text-anchor=\"end\">" << fmt(t)
      << "</text>\n";
  o << "<rect x=\"" << L << "\" y=\"" << T << "\" width=\"" << W - L - Rm << "\" height=\"" << H - T - B
    << "\" fill=\"none\" stroke=\"black\"/>\n";
  o << "<text x=\"" << W / 2 << "\" y=\"" << 24 << "\" text-anchor=\"middle\" font-size=\"16\">"
    << xml_escape(spec.title) << "</text>\n";
  o << "<text x=\"" << (L + W - Rm) / 2 << "\" y=\"" << H - 18 << "\" text-anchor=\"middle\">"
    << xml_escape(spec.xlabel) << "</text>\n";
  o << "<text transform=\"translate(22," << (T + H - B) / 2 << ") rotate(-90)\" text-anchor=\"middle\">"
    << xml_escape(spec.ylabel) << "</text>\n";
  int k = 0;
  for (const auto& s : spec.series) {
    o << "<polyline fill=\"none\" stroke=\"" << s.color << "\" stroke-width=\"1.6\""
      << (s.dashed ? " stroke-dasharray=\"6,4\"" : "") << " points=\"";
    for (std::size_t i = 0; i < s.x.size() && i < s.y.size(); ++i)
      if (std::isfinite(s.x[i]) && std::isfinite(s.y[i])) o << X(s.x[i]) << "," << Y(s.y[i]) << " ";
    o << "\"/>\n";
    const double ly = T + 20 + 18 * k++;  // legend, top right
    o << "<line x1=\"" << W - Rm - 330 << "\" y1=\"" << ly << "\" x2=\"" << W - Rm - 300 << "\" y2=\"" << ly
      << "\" stroke=\"" << s.color << "\" stroke-width=\"2\"" << (s.dashed ? " stroke-dasharray=\"6,4\"" : "")
      << "/><text x=\"" << W - Rm - 294 << "\" y=\"" << ly + 4 << "\">" << xml_escape(s.label) << "</text>\n";
  }
  o << "</svg>\n";
  if (!o) throw std::runtime_error(path.string() + ": error writing plot");
}

void write_png_plot(const std::filesystem::path& path, const PlotSpec& spec) {
  const std::filesystem::path script = std::filesystem::temp_directory_path() /
                                       ("ssimarch_plot_" + std::to_string(std::hash<std::string>{}(path.string())) + ".py");
  {
    std::ofstream o(script);
    if (!o) throw std::runtime_error("cannot write temporary plot script " + script.string());
    o << "import matplotlib\nmatplotlib.use('Agg')\nimport matplotlib.pyplot as plt\n"
      << "fig, ax = plt.subplots(figsize=(8, 5))\n";
    for (const auto& s : spec.series)
      o << "ax.plot(" << py_list(s.x) << ", " << py_list(s.y) << ", color=" << py_str(s.color)
        << ", linestyle=" << (s.dashed ? "'--'" : "'-'") << ", label=" << py_str(s.label) << ")\n";
    o << "ax.set_title(" << py_str(spec.title) << ")\nax.set_xlabel(" << py_str(spec.xlabel) << ")\nax.set_ylabel("
      << py_str(spec.ylabel) << ")\nax.grid(alpha=0.3)\nax.legend()\nfig.tight_layout()\nfig.savefig("
      << py_str(path.string()) << ", dpi=120)\n";
  }
  const std::string cmd = "/usr/bin/python3 '" + script.string() + "' >/dev/null 2>&1";
  const int rc = std::system(cmd.c_str());
  std::filesystem::remove(script);
  if (rc != 0)
    throw std::runtime_error("PNG plot failed (needs /usr/bin/python3 with matplotlib; use an .svg file instead)");
}

void write_plot(const std::filesystem::path& path, const PlotSpec& spec) {
  const std::string ext = path.extension().string();
  if (ext == ".svg") return write_svg_plot(path, spec);
  if (ext == ".png") return write_png_plot(path, spec);
  throw std::invalid_argument("plot file must end in .svg or .png: " + path.string());
}

}  // namespace ssimarch::porosity
