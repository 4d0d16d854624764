#include "ssimarch/march/order3_polynomial.hpp"

#include "ssimarch/geometry/curve_geometry.hpp"

namespace ssimarch {

Prediction Order3PolynomialPredictor::predict(const Problem& problem, const MarchState& s, double h) const {
  const CurveGeometry f = frenet_from_jet(s.here, problem.scale());
  const double h2 = h * h, h3 = h2 * h;
  Vec3 Q;
  if (f.has_frame()) {
    // Thesis eq 2.7 in world coordinates (standard torsion: + kappa tau L^3/6 b).
    Q = f.point + (h - f.kappa * f.kappa * h3 / 6) * f.t + (f.kappa * h2 / 2 + f.kappa_prime * h3 / 6) * f.n +
        (f.kappa * f.tau * h3 / 6) * f.b;
  } else {
    // kappa = 0, n and b undetermined (NaN): the same cubic written without the frame,
    // P + L t + (L^3/6) alpha''' (alpha'' = 0 here).
    const Vec3 alpha3 = s.here.order >= 3 ? Vec3(6.0 * s.here.alpha[3]) : Vec3::Zero();
    Q = f.point + h * f.t + (h3 / 6) * alpha3;
  }
  return internal::prediction_at(problem, s, Q, h);
}

}  // namespace ssimarch
