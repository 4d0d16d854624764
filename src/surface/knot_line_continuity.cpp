// C1 across knot lines and seams (include/ssimarch/surface/knot_line_continuity.hpp).
#include "ssimarch/surface/knot_line_continuity.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

namespace ssimarch::internal {
namespace {

using Poly = std::vector<double>;  // Bernstein coefficients

// The product of two Bernstein polynomials of degrees n and m (degree n + m).
Poly product(const Poly& a, const Poly& b) {
  const int n = static_cast<int>(a.size()) - 1, m = static_cast<int>(b.size()) - 1;
  Poly r(static_cast<std::size_t>(n + m + 1), 0.0);
  const auto binom = [](int top, int k) {
    double c = 1;
    for (int i = 1; i <= k; ++i) c = c * (top - k + i) / i;
    return c;
  };
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= m; ++j)
      r[static_cast<std::size_t>(i + j)] += binom(n, i) * binom(m, j) / binom(n + m, i + j) *
                                            a[static_cast<std::size_t>(i)] * b[static_cast<std::size_t>(j)];
  return r;
}

// The largest difference between x1 - x2 and y1 - y2 (polynomials of one degree) in *worst, and
// their largest coefficient in *scale: the defect is relative to the size of the terms over all
// three coordinates (a coordinate that vanishes at the join is compared with the others' size).
void accumulate(const Poly& x1, const Poly& x2, const Poly& y1, const Poly& y2, double* worst, double* scale) {
  for (std::size_t k = 0; k < x1.size(); ++k) {
    *scale = std::max({*scale, std::abs(x1[k]), std::abs(x2[k]), std::abs(y1[k]), std::abs(y2[k])});
    *worst = std::max(*worst, std::abs((x1[k] - x2[k]) - (y1[k] - y2[k])));
  }
}

struct Line {  // one boundary row (or column) of a piece: homogeneous component c of each point
  const std::array<double, 4>* net;
  int length;  // points along the line
  int stride;  // between them
  Poly operator()(std::size_t c) const {
    Poly r(static_cast<std::size_t>(length));
    for (int k = 0; k < length; ++k) r[static_cast<std::size_t>(k)] = net[k * stride][c];
    return r;
  }
};

// The relative defect of C0 (seams) and C1 between piece L (its rows `last`, `last - 1` at the
// line) and piece R (rows 0, 1), of widths hl and hr across the line.
double join_defect(Line l_end, Line l_before, Line r_start, Line r_after, double hl, double hr, bool seam) {
  const Poly wl = l_end(3), wl1 = l_before(3), wr = r_start(3), wr1 = r_after(3);
  const Poly wl_sq = product(wl, wl), wr_sq = product(wr, wr);
  double c0 = 0, c0_scale = 0, c1 = 0, c1_scale = 0;
  for (std::size_t c = 0; c < 3; ++c) {
    const Poly al = l_end(c), al1 = l_before(c), ar = r_start(c), ar1 = r_after(c);
    const Poly zero(2 * al.size() - 1, 0.0);
    if (seam) accumulate(product(al, wr), zero, product(ar, wl), zero, &c0, &c0_scale);
    Poly x1 = product(product(al, wl1), wr_sq), x2 = product(product(al1, wl), wr_sq);
    Poly y1 = product(product(ar1, wr), wl_sq), y2 = product(product(ar, wr1), wl_sq);
    for (auto* poly : {&x1, &x2})
      for (double& x : *poly) x /= hl;
    for (auto* poly : {&y1, &y2})
      for (double& y : *poly) y /= hr;
    accumulate(x1, x2, y1, y2, &c1, &c1_scale);
  }
  return std::max(c0_scale > 0 ? c0 / c0_scale : 0.0, c1_scale > 0 ? c1 / c1_scale : 0.0);
}

int multiplicity(std::span<const double> knots, double at) {
  return static_cast<int>(std::count(knots.begin(), knots.end(), at));
}

// The first kink across the lines of one direction (u: across = 0, rows of the pieces; v:
// columns).
std::optional<KnotLineKink> first_kink_along(const BezierExtraction& x, int across, std::span<const double> knots,
                                             bool periodic) {
  const std::vector<double>& breaks = across == 0 ? x.breaks_u : x.breaks_v;
  const int pieces = static_cast<int>(breaks.size()) - 1, others = across == 0 ? x.pieces_v() : x.pieces_u();
  const int degree = across == 0 ? x.p : x.q, cols = x.q + 1;
  const auto line = [&](int piece, int other, int r) {
    const int i = across == 0 ? piece : other, j = across == 0 ? other : piece;
    const std::array<double, 4>* net =
        x.nets.data() + static_cast<std::size_t>((i * x.pieces_v() + j) * (x.p + 1) * cols);
    return across == 0 ? Line{net + r * cols, cols, 1} : Line{net + r, x.p + 1, cols};
  };
  const auto width = [&](int k) {
    return breaks[static_cast<std::size_t>(k) + 1] - breaks[static_cast<std::size_t>(k)];
  };
  for (int k = periodic ? 0 : 1; k < pieces; ++k) {
    const bool seam = k == 0;
    const int left = seam ? pieces - 1 : k - 1;
    if (!seam && multiplicity(knots, breaks[static_cast<std::size_t>(k)]) < degree) continue;
    for (int o = 0; o < others; ++o) {
      const double d = join_defect(line(left, o, degree), line(left, o, degree - 1), line(k, o, 0), line(k, o, 1),
                                   width(left), width(k), seam);
      if (!(d <= kKnotLineC1Relative))
        return KnotLineKink{across == 0 ? 'u' : 'v', breaks[static_cast<std::size_t>(k)], d, seam};
    }
  }
  return std::nullopt;
}

}  // namespace

std::string KnotLineKink::describe() const {
  char line[200];
  if (seam)
    std::snprintf(line, sizeof line, "its closed seam at %c = %.9g is not C1 (relative defect %.2g)", parameter, at,
                  defect);
  else
    std::snprintf(line, sizeof line, "it is not C1 across the knot line %c = %.9g (relative defect %.2g)", parameter,
                  at, defect);
  return line;
}

std::optional<KnotLineKink> first_kink(const BezierExtraction& pieces, std::span<const double> knots_u,
                                       std::span<const double> knots_v, bool periodic_u, bool periodic_v) {
  if (auto k = first_kink_along(pieces, 0, knots_u, periodic_u)) return k;
  return first_kink_along(pieces, 1, knots_v, periodic_v);
}

}  // namespace ssimarch::internal
