// The differential geometry of a space curve at one point, as one small value type, and the
// Frenet formulas that produce it from derivatives (thesis §2.1).
//
// Conventions (docs/geometry.md):
//  * Torsion is the standard one, tau = (c' x c'') . c''' / |c' x c''|^2 (right-handed helix
//    positive; Frenet b' = -tau n). The thesis (seed 003) prints do Carmo's sign, tau_dC = -tau
//    (docs/geometry.md, torsion sign); use tau_do_carmo() to compare with its tables.
//  * n points to the centre of curvature, b = t x n.
//  * kappa_prime = d kappa / ds with s the arc length in the direction of t: it changes sign
//    with the orientation of t (kappa and tau do not).
//  * theta is the angle between the two surface normals, in [0, pi]; sin(theta) -> 0 at
//    tangential (singular) points.
//  * Quantities a method could not determine are NaN (JSON null), never 0; `status` says why.
#pragma once

#include <cmath>
#include <limits>
#include <optional>
#include <string>
#include <string_view>

#include "ssimarch/core/vec3.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch {

struct DynamicCurveJet;  // problem/curve_jet.hpp

/// Outcome of a geometry evaluation. Each status documents which fields are valid; the others
/// are NaN.
enum class GeometryStatus {
  kOk,                    // t, n, b, kappa, tau, kappa_prime, theta all valid.
  kZeroCurvature,         // kappa < zero_curvature: t, kappa, theta valid; n, b, tau,
                          // kappa_prime undefined (the osculating plane does not exist).
  kSingular,              // sin(theta) < singular_sin_theta (normals parallel) or the curve
                          // Jacobian is rank deficient, and the method needs a transversal point:
                          // only theta (and the point) valid.
  kTangentialSecondOrder, // tangential point handled by the Ye-Maekawa tangential formulas:
                          // t, n, b, kappa, theta valid; tau, kappa_prime undefined (the sources
                          // give no third-order tangential formulas).
  kIsolatedPoint,         // tangential point where no real curve direction exists
                          // (II_F - II_G definite): only theta valid.
  kHigherOrderContact,    // tangential point with II_F = II_G: directions not fixed at second
                          // order; only theta valid.
  kNotApplicable,         // the method does not apply to this pair kind (e.g. willmore needs two
                          // implicit surfaces): nothing valid.
  kInsufficientSamples,   // estimate: too few neighbouring samples; t and theta valid, and kappa,
                          // n, b too if one circle could be built (tau, kappa_prime need two).
  kNonFinite,             // surface derivatives not finite at this point: nothing valid.
};
std::string_view to_string(GeometryStatus status);

/// The methods of issue 4 (docs/geometry.md has the formulas and sources).
enum class GeometryMethod {
  kExact,           // implicit function theorem, order by order (problem/curve_jet.hpp)
  kYeMaekawa,       // transversal eqs 3.11-3.15, 3.23-3.25; tangential eqs 3.1-3.6, 3.16-3.22
  kWillmore,        // operator method, two implicit surfaces (seed 004 §4)
  kStoyanov,        // curvature vector from the Gram system of the two normals (eqs 3.8-3.9)
  kEstimate,        // tangents only: Wu-Andrade circle, binormal turning, eq 3.27
  kBarnhillKersey,  // the estimate with the three-point circle (eq 3.7) instead of Wu-Andrade
  kMixed,           // ye-maekawa where sin(theta) >= mixed_sin_theta, estimate below
};
std::string_view to_string(GeometryMethod method);
/// Parses the names printed by to_string ("exact", "ye-maekawa", "willmore", "stoyanov",
/// "estimate", "barnhill-kersey", "mixed"). Returns false (and leaves *out) on an unknown name.
bool parse(std::string_view name, GeometryMethod* out);
/// "exact, ye-maekawa, ..." for help texts and error messages.
std::string method_names();

inline constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

/// Tolerances of the geometry module (all have a unit and a default; docs/geometry.md).
struct GeometryTolerances {
  /// sin(theta) below which the normals count as parallel (dimensionless). Transversal formulas
  /// divide by sin^2(theta): below this they report kSingular, and ye-maekawa switches to its
  /// tangential formulas. About sqrt(machine epsilon): where two surfaces are tangent the
  /// residual is quadratic in the distance, so a point can only be located to ~1e-8 of a
  /// tangential point, where sin(theta) is of that order too.
  double singular_sin_theta = kTangentialSinTheta;
  /// Curvature below which the Frenet frame is undefined (1 / model length).
  double zero_curvature = 1e-12;
  /// mixed: ye-maekawa where sin(theta) >= this, estimate below (dimensionless; thesis §3.2
  /// and §4.3).
  double mixed_sin_theta = 0.1;
  /// Tangential formulas: discriminant of the direction quadratic below which the two
  /// directions count as one, relative to the squared size of II_F - II_G (dimensionless).
  double tangential_discriminant = 1e-12;
};

/// t, n, b, kappa, tau, kappa', theta of a curve at one point (conventions: file comment).
struct CurveGeometry {
  GeometryStatus status = GeometryStatus::kNonFinite;
  Vec3 point = Vec3::Constant(kNaN);
  Vec3 t = Vec3::Constant(kNaN);
  Vec3 n = Vec3::Constant(kNaN);
  Vec3 b = Vec3::Constant(kNaN);
  double kappa = kNaN;
  double tau = kNaN;          // standard sign (see file comment)
  double kappa_prime = kNaN;  // d kappa / ds along t
  double theta = kNaN;        // angle between the surface normals, radians in [0, pi]

  bool has_tangent() const { return t.allFinite(); }
  bool has_frame() const { return n.allFinite() && b.allFinite(); }
  /// The thesis' (do Carmo's) torsion, -tau (docs/geometry.md, torsion sign).
  double tau_do_carmo() const { return -tau; }
  /// Reverses the orientation of t: b and kappa' change sign, n, kappa, tau do not.
  void reverse();
};

/// The one Frenet builder (thesis §2.1, eqs 2.3-2.5; ch. 3, eqs 3.24-3.25): from `g` with its unit
/// tangent t and curvature kappa set, the curvature vector c2 = kappa n of an arc-length
/// parametrisation and, when known, its third derivative c3 (its part along t is not used):
///   n = c2/kappa, b = t x n, kappa' = c3.n, tau = c3.b/kappa (the standard sign).
/// kappa is |c2| unless the caller has a more accurate value (Ye-Maekawa's eq 3.15). Status kOk,
/// or kZeroCurvature where !(kappa > zero_curvature) (curvature units): n, b, kappa', tau stay NaN.
/// Every Frenet frame of the library is built here: from derivatives in any parameter, from
/// arc-length jets, and by the intersection formulas (geometry/intersection_geometry.hpp).
CurveGeometry frenet_frame(CurveGeometry g, const Vec3& curvature_vector, const Vec3* third_derivative,
                           double zero_curvature);

/// Frenet data of a curve from its first three derivatives with respect to any regular
/// parameter (thesis §2.1, eqs 2.3-2.5, 2.8), through frenet_frame with the arc-length derivatives
///   t = c1/|c1|, d2c/ds2 = (c1 x c2) x c1 / |c1|^4, d3c/ds3 = c3/|c1|^3 - 3 (c1.c2) c2/|c1|^5 (mod t),
/// which give kappa = |c1 x c2| / |c1|^3, tau = (c1 x c2).c3 / |c1 x c2|^2, b = unit(c1 x c2) and
///   kappa' = [ (w.(c1 x c3)) / (|w| |c1|^3) - 3 |w| (c1.c2) / |c1|^5 ] / |c1|,  w = c1 x c2
/// (derivation: docs/math/frenet.md). theta is left NaN. Status kOk, kZeroCurvature (kappa <=
/// tol.zero_curvature) or kNonFinite (c1 = 0 or not finite).
CurveGeometry frenet_from_derivatives(const Vec3& c1, const Vec3& c2, const Vec3& c3,
                                      const GeometryTolerances& tol = {});

/// kappa times the problem's length scale at or below which a curve counts as straight at a
/// point (dimensionless): its Frenet frame is then undetermined.
inline constexpr double kStraightCurvature = 1e-12;

/// The same frame from an arc-length jet alpha(s) = sum alpha_k s^k (problem/curve_jet.hpp),
/// where |alpha'| = 1 and alpha' . alpha'' = 0 reduce the formulas above to
///   kappa = |alpha''|, n = alpha''/kappa, b = t x n, kappa' = alpha'''.n, tau = alpha'''.b/kappa
/// (thesis §2.1, eqs 2.3-2.5). The marching predictors and step rules use it. Status kOk, or
/// kZeroCurvature where kappa * length_scale <= kStraightCurvature (n, b, tau, kappa' NaN); a jet
/// of order 2 determines no third derivative (tau, kappa' NaN), one of order 1 no curvature
/// (kZeroCurvature with kappa = 0); kSingular / kNonFinite when the jet is. theta is left NaN.
CurveGeometry frenet_from_jet(const DynamicCurveJet& jet, double length_scale);

/// Angle between two unit normals, atan2(|a x b|, a.b), in [0, pi].
double normal_angle(const Vec3& a, const Vec3& b);

}  // namespace ssimarch
