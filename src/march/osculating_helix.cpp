#include "ssimarch/march/osculating_helix.hpp"

#include <cmath>

#include "ssimarch/geometry/curve_geometry.hpp"

namespace ssimarch {

Prediction OsculatingHelixPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  const CurveGeometry f = frenet_from_jet(s.here, problem.scale());
  // kappa = 0 (n, b, tau NaN): the helix degenerates to its axis direction, a straight segment.
  if (!f.has_frame()) return internal::prediction_at(problem, s, f.point + h * f.t, h);
  // Thesis eq 2.9 placed at P in the Frenet frame, with a = kappa/w^2, bh = tau_dC/w^2,
  // c = 1/w, w = sqrt(kappa^2 + tau^2), and the corrected last coefficient (a bh/c^2) L.
  const double tau_dC = -f.tau;
  const double w2 = f.kappa * f.kappa + f.tau * f.tau, w = std::sqrt(w2);
  const double a = f.kappa / w2, bh = tau_dC / w2, c = 1.0 / w;
  const double phi = h / c, sn = std::sin(phi);
  const double one_minus_cos = 2 * std::sin(phi / 2) * std::sin(phi / 2);
  const Vec3 Q = f.point + ((a * a / c) * sn + (bh * bh / (c * c)) * h) * f.t + (a * one_minus_cos) * f.n +
                 ((a * bh / c) * sn - (a * bh / (c * c)) * h) * f.b;
  return internal::prediction_at(problem, s, Q, h);
}

}  // namespace ssimarch
