#include "ssimarch/io/svg_plot.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <iomanip>
#include <sstream>
#include <vector>

#include "ssimarch/io/svg_canvas.hpp"

namespace ssimarch {

namespace {

const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#9467bd", "#ff7f0e", "#17becf", "#8c564b", "#e377c2"};

struct Panel {
  std::string title, xlabel, ylabel;
  // Polylines in panel coordinates, each with its curve index; breaks where a periodic
  // parameter wraps.
  std::vector<std::pair<int, std::vector<Vec2>>> lines;
  std::vector<std::pair<int, Vec2>> ends;  // open ends
  std::vector<std::pair<std::string, Vec2>> marks;  // singular and isolated points with their type
  double xmin = 0, xmax = 1, ymin = 0, ymax = 1;
  bool fixed_range = false;
};

void fit(Panel* p) {
  if (p->fixed_range) return;
  double x0 = std::numeric_limits<double>::infinity(), x1 = -x0, y0 = x0, y1 = -x0;
  for (const auto& [c, l] : p->lines)
    for (const Vec2& q : l) {
      x0 = std::min(x0, q.x());
      x1 = std::max(x1, q.x());
      y0 = std::min(y0, q.y());
      y1 = std::max(y1, q.y());
    }
  if (!std::isfinite(x0)) return;
  double pad = 0.05 * std::max({x1 - x0, y1 - y0, 1e-9});
  // Equal scales on both axes (a 3D view or a plane section must not be distorted).
  double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1), half = 0.5 * std::max(x1 - x0, y1 - y0) + pad;
  p->xmin = cx - half;
  p->xmax = cx + half;
  p->ymin = cy - half;
  p->ymax = cy + half;
}

void draw(SvgCanvas& svg, const Panel& p, double ox, int size) {
  const double m = 36;  // margin for labels
  double w = size - 2 * m;
  const PlotBox box{ox + m, m, w, w, p.xmin, p.xmax, p.ymin, p.ymax};
  svg.rect(ox + m, m, w, w, "fill='white' stroke='#999'");
  svg.text(ox + size / 2.0, m - 14, "text-anchor='middle' font-size='14'") << xml_escape(p.title);
  svg.end_text();
  svg.text(ox + size / 2.0, m + w + 24, "text-anchor='middle' font-size='12'")
      << p.xlabel << " [" << std::setprecision(3) << p.xmin << ", " << p.xmax << "]";
  svg.end_text();
  svg.vertical_text(ox + 14, m + w / 2, "text-anchor='middle' font-size='12'")
      << p.ylabel << " [" << p.ymin << ", " << p.ymax << "]";
  svg.end_text();
  svg.stream() << std::setprecision(6);
  for (const auto& [c, l] : p.lines) {
    if (l.size() < 2) continue;
    std::vector<Vec2> pixels;
    pixels.reserve(l.size());
    for (const Vec2& q : l) pixels.emplace_back(box.px(q.x()), box.py(q.y()));
    svg.polyline(pixels, std::string("fill='none' stroke-width='1.6' stroke='") + kColors[c % 8] + "'");
  }
  for (const auto& [c, q] : p.ends)
    svg.circle(box.px(q.x()), box.py(q.y()), 3.5, std::string("fill='none' stroke='") + kColors[c % 8] + "'");
  for (const auto& [type, q] : p.marks) {
    svg.rect(box.px(q.x()) - 3, box.py(q.y()) - 3, 6, 6, "fill='black'");
    svg.text(box.px(q.x()) + 6, box.py(q.y()) - 6, "font-size='11'") << type;
    svg.end_text();
  }
}

// The singular and isolated points of the run, mapped into a panel by `map`.
template <class Map>
void mark_singular_points(const TraceResult& r, Panel* p, Map map) {
  for (const auto* list : {&r.singular_points, &r.isolated_points})
    for (const SingularPointReport& s : *list) p->marks.push_back({std::string(to_string(s.type)), map(s)});
}

// The 3D view: along the principal axes of the points (the plane of largest spread faces the
// reader), or axonometric at the options' azimuth and elevation.
Panel view_panel(const IntersectionRun& run, const SvgOptions& o) {
  const auto& curves = run.result.curves;
  double az = o.azimuth_deg * M_PI / 180, el = o.elevation_deg * M_PI / 180;
  Vec3 right(std::cos(az), std::sin(az), 0), up(-std::sin(az) * std::sin(el), std::cos(az) * std::sin(el), std::cos(el));
  std::string view_title = "3D view (azimuth " + std::to_string(static_cast<int>(o.azimuth_deg)) + "\u00b0)";
  if (!o.axonometric) {
    Vec3 mean = Vec3::Zero();
    long count = 0;
    for (const auto& c : curves)
      for (const auto& p : c.points) {
        mean += p.p;
        ++count;
      }
    if (count > 2) {
      mean /= static_cast<double>(count);
      Eigen::Matrix3d cov = Eigen::Matrix3d::Zero();
      for (const auto& c : curves)
        for (const auto& p : c.points) cov += (p.p - mean) * (p.p - mean).transpose();
      Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(cov);  // eigenvalues ascending
      right = eig.eigenvectors().col(2);
      up = eig.eigenvectors().col(1);
      Vec3 look = right.cross(up);
      std::ostringstream os;
      os << std::setprecision(2) << std::fixed << "(" << look.x() << ", " << look.y() << ", " << look.z() << ")";
      view_title = "3D view along " + os.str();
    }
  }
  Panel view{view_title, "screen x", "screen y", {}, {}, {}};
  for (std::size_t ci = 0; ci < curves.size(); ++ci) {
    std::vector<Vec2> l;
    for (const auto& p : curves[ci].points) l.emplace_back(p.p.dot(right), p.p.dot(up));
    if (!curves[ci].closed && !l.empty()) {
      view.ends.push_back({static_cast<int>(ci), l.front()});
      view.ends.push_back({static_cast<int>(ci), l.back()});
    }
    view.lines.push_back({static_cast<int>(ci), std::move(l)});
  }
  mark_singular_points(run.result, &view, [&](const SingularPointReport& s) { return Vec2(s.p.dot(right), s.p.dot(up)); });
  fit(&view);
  return view;
}

// The curves in the plane of unknowns a and b: a surface's parameter domain (a line broken where
// a periodic unknown wraps), or an orthographic view of an implicit pair.
Panel unknowns_panel(const IntersectionRun& run, int a, int b) {
  const Problem& P = run.problem;
  const auto& curves = run.result.curves;
  const auto names = P.unknown_names();
  Panel p;
  bool param = P.kind() != PairKind::kImplicitImplicit;
  std::string which =
      param ? (a == 0 ? run.spec.swapped ? run.spec.surfaces[1] : run.spec.surfaces[0] : run.spec.surfaces[1]) : "";
  p.title = param ? "domain of " + which : (b == 1 ? "top view (x, y)" : "front view (x, z)");
  p.xlabel = names[static_cast<std::size_t>(a)];
  p.ylabel = names[static_cast<std::size_t>(b)];
  if (param) {
    const Interval &ia = P.bounds()[static_cast<std::size_t>(a)], &ib = P.bounds()[static_cast<std::size_t>(b)];
    p.xmin = ia.lo;
    p.xmax = ia.hi;
    p.ymin = ib.lo;
    p.ymax = ib.hi;
    p.fixed_range = true;
  }
  const double pa = P.periods()[static_cast<std::size_t>(a)], pb = P.periods()[static_cast<std::size_t>(b)];
  for (std::size_t ci = 0; ci < curves.size(); ++ci) {
    std::vector<Vec2> l;
    const CurvePoint* prev = nullptr;
    for (const auto& q : curves[ci].points) {
      const bool wrapped = prev && ((pa > 0 && std::fabs(q.x[a] - prev->x[a]) > pa / 2) ||
                                    (pb > 0 && std::fabs(q.x[b] - prev->x[b]) > pb / 2));
      if (wrapped) {
        p.lines.push_back({static_cast<int>(ci), std::move(l)});
        l.clear();
      }
      l.emplace_back(q.x[a], q.x[b]);
      prev = &q;
    }
    if (!curves[ci].closed && !curves[ci].points.empty()) {
      const auto& f = curves[ci].points.front().x;
      const auto& e = curves[ci].points.back().x;
      p.ends.push_back({static_cast<int>(ci), Vec2(f[a], f[b])});
      p.ends.push_back({static_cast<int>(ci), Vec2(e[a], e[b])});
    }
    p.lines.push_back({static_cast<int>(ci), std::move(l)});
  }
  mark_singular_points(run.result, &p, [&](const SingularPointReport& s) { return Vec2(s.x[a], s.x[b]); });
  fit(&p);
  return p;
}

// Under the panels: the intersection, its surfaces and counts, then one line per curve (8 at most).
void write_legend(SvgCanvas& svg, const IntersectionRun& run, double y) {
  const auto& curves = run.result.curves;
  svg.text(12, y, "font-size='13' font-weight='bold'")
      << xml_escape(run.spec.name) << ": " << xml_escape(run.spec.surfaces[0]) << " \u2229 "
      << xml_escape(run.spec.surfaces[1]) << " (" << to_string(run.problem.kind()) << ", " << run.result.stats.points
      << " points, " << std::setprecision(4) << run.result.stats.time_ms << " ms)";
  svg.end_text();
  for (std::size_t ci = 0; ci < std::min<std::size_t>(curves.size(), 8); ++ci) {
    y += 18;
    const auto& c = curves[ci];
    svg.text(24, y, std::string("font-size='12' fill='") + kColors[ci % 8] + "'")
        << "curve " << ci << ": "
        << (c.closed ? "closed" : "open (" + std::string(to_string(c.start_end)) + " / " + std::string(to_string(c.end_end)) + ")")
        << ", length " << std::setprecision(10) << c.length << ", " << c.points.size() << " points";
    svg.end_text();
  }
}

}  // namespace

void write_svg(std::ostream& out, const IntersectionRun& run, const SvgOptions& o) {
  const Problem& P = run.problem;
  std::vector<Panel> panels{view_panel(run, o)};
  // Parameter domains (pairs of unknowns), or two orthographic views for implicit pairs.
  std::vector<std::pair<int, int>> pairs;
  if (P.kind() == PairKind::kImplicitImplicit)
    pairs = {{0, 1}, {0, 2}};
  else if (P.kind() == PairKind::kParametricImplicit)
    pairs = {{0, 1}};
  else
    pairs = {{0, 1}, {2, 3}};
  for (const auto& [a, b] : pairs) panels.push_back(unknowns_panel(run, a, b));

  const int S = o.panel_size;
  const std::size_t legend_lines = std::min<std::size_t>(run.result.curves.size(), 8);
  const int width = S * static_cast<int>(panels.size()), height = S + 60 + 18 * static_cast<int>(legend_lines);
  SvgCanvas svg(out, width, height, "font-family='sans-serif'", "#fafafa");
  for (std::size_t i = 0; i < panels.size(); ++i)
    draw(svg, panels[i], static_cast<double>(i * static_cast<std::size_t>(S)), S);
  write_legend(svg, run, S + 20);
  svg.finish();
}

}  // namespace ssimarch
