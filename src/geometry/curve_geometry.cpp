#include "ssimarch/geometry/curve_geometry.hpp"

#include <array>
#include <utility>

#include "ssimarch/problem/curve_jet.hpp"

namespace ssimarch {

namespace {
constexpr std::array<std::pair<GeometryMethod, std::string_view>, 7> kMethodNames{{
    {GeometryMethod::kExact, "exact"},
    {GeometryMethod::kYeMaekawa, "ye-maekawa"},
    {GeometryMethod::kWillmore, "willmore"},
    {GeometryMethod::kStoyanov, "stoyanov"},
    {GeometryMethod::kEstimate, "estimate"},
    {GeometryMethod::kBarnhillKersey, "barnhill-kersey"},
    {GeometryMethod::kMixed, "mixed"},
}};
}  // namespace

std::string_view to_string(GeometryStatus status) {
  switch (status) {
    case GeometryStatus::kOk: return "ok";
    case GeometryStatus::kZeroCurvature: return "zero-curvature";
    case GeometryStatus::kSingular: return "singular";
    case GeometryStatus::kTangentialSecondOrder: return "tangential-second-order";
    case GeometryStatus::kIsolatedPoint: return "isolated-point";
    case GeometryStatus::kHigherOrderContact: return "higher-order-contact";
    case GeometryStatus::kNotApplicable: return "not-applicable";
    case GeometryStatus::kInsufficientSamples: return "insufficient-samples";
    case GeometryStatus::kNonFinite: return "non-finite";
  }
  return "unknown";
}

std::string_view to_string(GeometryMethod method) {
  for (const auto& [m, name] : kMethodNames)
    if (m == method) return name;
  return "unknown";
}

bool parse(std::string_view name, GeometryMethod* out) {
  for (const auto& [m, n] : kMethodNames)
    if (n == name) {
      *out = m;
      return true;
    }
  return false;
}

std::string method_names() {
  std::string r;
  for (const auto& [m, n] : kMethodNames) {
    if (!r.empty()) r += ", ";
    r += n;
  }
  return r;
}

void CurveGeometry::reverse() {
  t = -t;
  b = -b;
  kappa_prime = -kappa_prime;
}

double normal_angle(const Vec3& a, const Vec3& b) { return std::atan2(a.cross(b).norm(), a.dot(b)); }

CurveGeometry frenet_frame(CurveGeometry g, const Vec3& curvature_vector, const Vec3* third_derivative,
                           double zero_curvature) {
  if (!(g.kappa > zero_curvature)) {
    g.status = GeometryStatus::kZeroCurvature;
    return g;
  }
  g.n = curvature_vector / g.kappa;
  g.b = g.t.cross(g.n);
  if (third_derivative) {
    g.kappa_prime = third_derivative->dot(g.n);
    g.tau = third_derivative->dot(g.b) / g.kappa;
  }
  g.status = GeometryStatus::kOk;
  return g;
}

// Thesis §2.1, eqs 2.3-2.5 and 2.8: d/ds = (1/|c1|) d/du turns the parameter's derivatives into
// the arc length's (docs/math/frenet.md).
CurveGeometry frenet_from_derivatives(const Vec3& c1, const Vec3& c2, const Vec3& c3, const GeometryTolerances& tol) {
  CurveGeometry g;
  const double speed = c1.norm();
  if (!(c1.allFinite() && c2.allFinite() && c3.allFinite()) || speed == 0.0) {
    g.status = GeometryStatus::kNonFinite;
    return g;
  }
  g.t = c1 / speed;
  const Vec3 w = c1.cross(c2);
  const double s2 = speed * speed, s3 = s2 * speed;
  g.kappa = w.norm() / s3;
  const Vec3 curvature_vector = w.cross(c1) / (s2 * s2);
  const Vec3 third = c3 / s3 - 3.0 * c1.dot(c2) * c2 / (s3 * s2);
  return frenet_frame(g, curvature_vector, &third, tol.zero_curvature);
}

CurveGeometry frenet_from_jet(const DynamicCurveJet& jet, double length_scale) {
  CurveGeometry g;
  g.point = jet.alpha[0];
  if (jet.status != CurveJetStatus::kOk) {
    g.status = jet.status == CurveJetStatus::kSingular ? GeometryStatus::kSingular : GeometryStatus::kNonFinite;
    return g;
  }
  g.t = jet.alpha[1];
  const Vec3 alpha2 = jet.order >= 2 ? Vec3(2.0 * jet.alpha[2]) : Vec3::Zero();
  g.kappa = alpha2.norm();
  const Vec3 alpha3 = jet.order >= 3 ? Vec3(6.0 * jet.alpha[3]) : Vec3::Zero();
  return frenet_frame(g, alpha2, jet.order >= 3 ? &alpha3 : nullptr, kStraightCurvature / length_scale);
}

}  // namespace ssimarch
