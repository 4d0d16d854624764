#include "ssimarch/geometry/quintic_hermite.hpp"

#include <cmath>

#include "ssimarch/core/gauss_legendre.hpp"

namespace ssimarch {

namespace {

// Control points of a Bézier curve of degree m raised to degree m + 1 (Piegl & Tiller eq. 5.36).
std::vector<VecX> elevate(const std::vector<VecX>& b) {
  const int m = static_cast<int>(b.size()) - 1;
  std::vector<VecX> e(static_cast<std::size_t>(m + 2));
  e.front() = b.front();
  e.back() = b.back();
  for (int i = 1; i <= m; ++i) {
    const double a = static_cast<double>(i) / (m + 1);
    e[static_cast<std::size_t>(i)] = a * b[static_cast<std::size_t>(i - 1)] + (1 - a) * b[static_cast<std::size_t>(i)];
  }
  return e;
}

}  // namespace

VecX QuinticPiece::at(double u) const {
  std::array<VecX, 6> w = bezier;
  for (int r = 1; r < 6; ++r)
    for (int i = 0; i + r < 6; ++i)
      w[static_cast<std::size_t>(i)] = (1 - u) * w[static_cast<std::size_t>(i)] + u * w[static_cast<std::size_t>(i + 1)];
  return w[0];
}

VecX QuinticPiece::derivative(double u) const {
  std::array<VecX, 5> w;
  for (std::size_t i = 0; i < 5; ++i) w[i] = 5.0 * (bezier[i + 1] - bezier[i]);
  for (int r = 1; r < 5; ++r)
    for (int i = 0; i + r < 5; ++i)
      w[static_cast<std::size_t>(i)] = (1 - u) * w[static_cast<std::size_t>(i)] + u * w[static_cast<std::size_t>(i + 1)];
  return w[0] / h;
}

QuinticPiece quintic_hermite(const HermiteEnd& a, const HermiteEnd& b, double h) {
  // The Bézier points next to an end are fixed by that end's derivatives (docs/math/curve_spline.md
  // §1): B1 = B0 + h/5 P', B2 = B0 + 2h/5 P' + h^2/20 P''. With all data the quintic is complete;
  // otherwise the interpolant of the lower degree m = (orders + 1) * 2 - 1 - missing is built on the
  // same rule with its own weights and elevated.
  const int m = a.order + b.order + 1;  // degree fixed by the conditions (2 + 2 + 1 = 5)
  std::vector<VecX> c(static_cast<std::size_t>(m + 1));
  const double hm = h / m;
  c.front() = a.value;
  c.back() = b.value;
  if (a.order >= 1) c[1] = a.value + hm * a.first;
  if (b.order >= 1) c[static_cast<std::size_t>(m - 1)] = b.value - hm * b.first;
  // Second derivative at u=0 of a degree-m Bézier: m(m-1)/h^2 (B2 - 2 B1 + B0).
  const double w2 = h * h / (m * (m - 1.0));
  if (a.order >= 2) c[2] = 2.0 * c[1] - c[0] + w2 * a.second;
  if (b.order >= 2) c[static_cast<std::size_t>(m - 2)] = 2.0 * c[static_cast<std::size_t>(m - 1)] - c.back() + w2 * b.second;
  while (static_cast<int>(c.size()) < 6) c = elevate(c);
  QuinticPiece p;
  p.h = h;
  for (std::size_t i = 0; i < 6; ++i) p.bezier[i] = c[i];
  return p;
}

double piece_length_3d(const QuinticPiece& piece) {
  const auto& x = kGaussLegendre8Nodes;
  const auto& w = kGaussLegendre8Weights;
  double sum = 0;
  for (int i = 0; i < 4; ++i)
    for (double sign : {-1.0, 1.0}) sum += w[i] * piece.derivative(0.5 + 0.5 * sign * x[i]).head<3>().norm();
  return 0.5 * piece.h * sum;
}

}  // namespace ssimarch
