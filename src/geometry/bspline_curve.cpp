#include "ssimarch/geometry/bspline_curve.hpp"

#include <algorithm>
#include <stdexcept>

#include "ssimarch/core/contract.hpp"

namespace ssimarch {

VecX BSplineCurve::at(double t) const {
  const int p = degree;
  const int n = static_cast<int>(control_points.size());
  t = std::clamp(t, start(), end());
  // The span k with knots[k] <= t < knots[k+1], k in [p, n-1].
  int k = static_cast<int>(std::upper_bound(knots.begin() + p, knots.begin() + n, t) - knots.begin()) - 1;
  k = std::clamp(k, p, n - 1);
  std::vector<VecX> d(static_cast<std::size_t>(p + 1));
  for (int j = 0; j <= p; ++j) d[static_cast<std::size_t>(j)] = control_points[static_cast<std::size_t>(j + k - p)];
  for (int r = 1; r <= p; ++r)
    for (int j = p; j >= r; --j) {
      const double lo = knots[static_cast<std::size_t>(j + k - p)];
      const double hi = knots[static_cast<std::size_t>(j + 1 + k - r)];
      const double a = hi > lo ? (t - lo) / (hi - lo) : 0.0;
      d[static_cast<std::size_t>(j)] = (1 - a) * d[static_cast<std::size_t>(j - 1)] + a * d[static_cast<std::size_t>(j)];
    }
  return d[static_cast<std::size_t>(p)];
}

BSplineCurve BSplineCurve::slice(int first, int count) const {
  BSplineCurve s{degree, periodic, knots, {}};
  for (const VecX& c : control_points) s.control_points.push_back(c.segment(first, count));
  return s;
}

void BSplineCurve::distinct_knots(std::vector<double>* values, std::vector<int>* multiplicities) const {
  values->clear();
  multiplicities->clear();
  for (double k : knots) {
    if (!values->empty() && values->back() == k) ++multiplicities->back();
    else {
      values->push_back(k);
      multiplicities->push_back(1);
    }
  }
}

namespace {

// The control point f(a, b, b, b, c) shared by two pieces meeting C2 at b (docs/math/curve_spline.md
// §2): from either side by affinity of the blossom in its last argument; the mean of both.
VecX shared_point(const QuinticPiece& left, const QuinticPiece& right) {
  const double r = right.h / left.h;
  const VecX from_left = left.bezier[4] + r * (left.bezier[4] - left.bezier[3]);
  const VecX from_right = right.bezier[1] + (1 / r) * (right.bezier[1] - right.bezier[2]);
  return 0.5 * (from_left + from_right);
}

void push_knot(std::vector<double>* knots, double t, int multiplicity) {
  for (int i = 0; i < multiplicity; ++i) knots->push_back(t);
}

BSplineCurve clamped(const std::vector<QuinticPiece>& pieces, const std::vector<int>& continuity) {
  BSplineCurve c;
  const std::size_t n = pieces.size();
  double t = 0;
  push_knot(&c.knots, t, 6);
  c.control_points = {pieces[0].bezier[0], pieces[0].bezier[1]};
  for (std::size_t i = 0; i < n; ++i) {
    c.control_points.push_back(pieces[i].bezier[2]);
    c.control_points.push_back(pieces[i].bezier[3]);
    t += pieces[i].h;
    if (i + 1 == n) break;
    if (continuity[i] >= 2) {
      c.control_points.push_back(shared_point(pieces[i], pieces[i + 1]));
      push_knot(&c.knots, t, 3);
    } else if (continuity[i] == 1) {
      // C1: the common point f(b, b, b, b, b) is the affine combination of its neighbours
      // f(a, b, b, b, b) = B4 (left) and f(b, b, b, b, c) = B1 (right), so it is removed.
      c.control_points.push_back(pieces[i].bezier[4]);
      c.control_points.push_back(pieces[i + 1].bezier[1]);
      push_knot(&c.knots, t, 4);
    } else {
      c.control_points.push_back(pieces[i].bezier[4]);
      c.control_points.push_back(pieces[i].bezier[5]);
      c.control_points.push_back(pieces[i + 1].bezier[1]);
      push_knot(&c.knots, t, 5);
    }
  }
  c.control_points.push_back(pieces[n - 1].bezier[4]);
  c.control_points.push_back(pieces[n - 1].bezier[5]);
  push_knot(&c.knots, t, 6);
  return c;
}

// Knots u_3 = u_4 = u_5 = 0 begin the domain; control point j is the blossom of u_{j+1..j+5}:
// d_0 = B3 of the last piece, then (Q_i, B2_i, B3_i) per piece, then d_1..d_4 again.
BSplineCurve periodic_form(const std::vector<QuinticPiece>& pieces) {
  BSplineCurve c;
  c.periodic = true;
  const std::size_t n = pieces.size();
  std::vector<double> breaks{0};
  for (const QuinticPiece& p : pieces) breaks.push_back(breaks.back() + p.h);
  const double period = breaks.back();
  // Break i of the periodic sequence, any integer i >= -1.
  auto s = [&](long i) {
    const long m = static_cast<long>(n);
    const long q = (i + m) / m - 1, r = (i + m) % m;
    return breaks[static_cast<std::size_t>(r)] + static_cast<double>(q) * period;
  };
  push_knot(&c.knots, s(-1), 3);
  for (std::size_t i = 0; i <= n + 1; ++i) push_knot(&c.knots, s(static_cast<long>(i)), 3);
  push_knot(&c.knots, s(static_cast<long>(n) + 2), 2);  // n_cp + 6 knots with n_cp = 3n + 5
  c.control_points.push_back(pieces[n - 1].bezier[3]);
  for (std::size_t i = 0; i < n; ++i) {
    c.control_points.push_back(shared_point(pieces[(i + n - 1) % n], pieces[i]));
    c.control_points.push_back(pieces[i].bezier[2]);
    c.control_points.push_back(pieces[i].bezier[3]);
  }
  for (std::size_t j = 1; j <= 4; ++j) c.control_points.push_back(c.control_points[j]);
  return c;
}

}  // namespace

BSplineCurve bspline_from_pieces(const std::vector<QuinticPiece>& pieces, const std::vector<int>& continuity, bool periodic) {
  SSIMARCH_EXPECTS(!pieces.empty(), "bspline_from_pieces: no pieces");
  if (!periodic) return clamped(pieces, continuity);
  SSIMARCH_EXPECTS(std::none_of(continuity.begin(), continuity.end(), [](int c) { return c < 2; }),
                   "bspline_from_pieces: a periodic spline needs C2 joins everywhere");
  return periodic_form(pieces);
}

}  // namespace ssimarch
