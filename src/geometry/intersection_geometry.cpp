#include "ssimarch/geometry/intersection_geometry.hpp"

#include <cmath>
#include <limits>

#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/geometry/intersection_formulas.hpp"
#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/gauss_newton.hpp"

namespace ssimarch {

namespace {

SurfaceLocal parametric_of(const Surface& s, double u, double v) {
  return parametric_local([&](const auto& a, const auto& b) { return s.point(a, b); }, u, v);
}
SurfaceLocal implicit_of(const Surface& s, const Vec3& p) {
  return implicit_local([&](const auto& q) { return s.value(q); }, p);
}

CurveGeometry with_status(const Vec3& point, GeometryStatus status) {
  CurveGeometry g;
  g.point = point;
  g.status = status;
  return g;
}

// The estimate on the samples previous..x..next (tangents from eq 2.19 / 3.6, oriented along the
// sample order).
CurveGeometry estimate_geometry(const Problem& problem, const VecX& x, EstimateCircle circle,
                                const GeometryContext& ctx) {
  // Samples that repeat their predecessor's point (a closed curve's closing point) carry no
  // information and would make a zero chord: they are dropped.
  const Vec3 p_here = problem.point(x);
  const double same = 1e-12 * std::max(1.0, p_here.norm());
  std::vector<VecX> xs;
  for (const VecX& xi : ctx.previous)
    if (xs.empty() || (problem.point(xi) - problem.point(xs.back())).norm() > same) xs.push_back(xi);
  while (!xs.empty() && (problem.point(xs.back()) - p_here).norm() <= same) xs.pop_back();
  const std::size_t here = xs.size();
  xs.push_back(x);
  for (const VecX& xi : ctx.next)
    if ((problem.point(xi) - problem.point(xs.back())).norm() > same) xs.push_back(xi);
  const bool has_next = xs.size() > here + 1;
  std::vector<CurveSample> samples;
  std::vector<std::pair<SurfaceLocal, SurfaceLocal>> locals;
  for (const VecX& xi : xs) {
    auto l = surface_locals(problem, xi);
    if (!l) return with_status(problem.point(x), GeometryStatus::kNonFinite);
    locals.push_back(*l);
    samples.push_back({local_point(l->first), Vec3::Constant(kNaN)});
  }
  const Vec3* hint_here = ctx.orientation ? &*ctx.orientation : nullptr;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    // Direction of travel at sample i: its chord through the neighbours.
    Vec3 along = samples[std::min(i + 1, samples.size() - 1)].point - samples[i > 0 ? i - 1 : 0].point;
    const Vec3* hint = along.norm() > 0 ? &along : hint_here;
    samples[i].tangent = intersection_tangent(locals[i].first, locals[i].second, hint, ctx.tolerances);
  }
  const auto& [first, second] = locals[here];
  Vec3 n1 = unit_normal(first), n2 = unit_normal(second);
  double theta = normal_angle(n1, n2);
  CurveGeometry g;
  if (has_next || here == 0) {
    g = estimate_from_samples(samples, here, circle, ctx.tolerances);
  } else {
    // No forward neighbour: the thesis' estimate at the previous sample, reported at x.
    CurveGeometry lag = estimate_from_samples(samples, here - 1, circle, ctx.tolerances);
    g = lag;
    g.point = samples[here].point;
    g.t = samples[here].tangent;
    if (lag.has_frame() && g.t.allFinite()) {
      Vec3 b = g.t.cross(lag.n);
      if (b.norm() > 0) {
        g.b = b.normalized();
        g.n = g.b.cross(g.t);
      }
    } else if (!g.t.allFinite()) {
      g = with_status(samples[here].point, GeometryStatus::kSingular);
    }
  }
  g.theta = theta;
  if (!g.t.allFinite() && g.status != GeometryStatus::kNonFinite) g.status = GeometryStatus::kSingular;
  if (ctx.orientation && g.t.allFinite() && g.t.dot(*ctx.orientation) < 0) g.reverse();
  return g;
}

}  // namespace

std::optional<std::pair<SurfaceLocal, SurfaceLocal>> surface_locals(const Problem& problem, const VecX& x,
                                                                     bool implicit_forms) {
  const Surface& a = problem.first();
  const Surface& b = problem.second();
  if (implicit_forms) {
    if (!a.is_implicit() || !b.is_implicit()) return std::nullopt;
    Vec3 p = problem.point(x);
    return std::pair{implicit_of(a, p), implicit_of(b, p)};
  }
  switch (problem.kind()) {
    case PairKind::kParametricParametric:
      return std::pair{parametric_of(a, x[0], x[1]), parametric_of(b, x[2], x[3])};
    case PairKind::kParametricImplicit: {
      SurfaceLocal f = parametric_of(a, x[0], x[1]);
      return std::pair{f, implicit_of(b, local_point(f))};
    }
    case PairKind::kImplicitImplicit: {
      Vec3 p(x[0], x[1], x[2]);
      return std::pair{implicit_of(a, p), implicit_of(b, p)};
    }
  }
  return std::nullopt;
}

CurveGeometry exact_geometry(const Problem& problem, const VecX& x, const Vec3* orientation,
                             const GeometryTolerances& tol) {
  CurveJet<3> jet = curve_jet<3>(problem, x, orientation);
  CurveGeometry g;
  double theta = kNaN;
  if (auto l = surface_locals(problem, x)) theta = normal_angle(unit_normal(l->first), unit_normal(l->second));
  if (std::fabs(std::sin(theta)) < tol.singular_sin_theta) {
    // Not distinguishable from a tangential point (see GeometryTolerances): the jet's solves
    // would amplify rounding by 1 / sin(theta) per order.
    g.status = GeometryStatus::kSingular;
  } else if (jet.status == CurveJetStatus::kOk) {
    g = frenet_from_derivatives(jet.derivative(1), jet.derivative(2), jet.derivative(3), tol);
  } else {
    g.status = jet.status == CurveJetStatus::kSingular ? GeometryStatus::kSingular : GeometryStatus::kNonFinite;
  }
  g.point = problem.point(x);
  g.theta = theta;
  return g;
}

CurveGeometry evaluate_geometry(const Problem& problem, const VecX& x, GeometryMethod method,
                                const GeometryContext& ctx) {
  if (x.size() != problem.dim() || !x.allFinite()) return with_status(Vec3::Constant(kNaN), GeometryStatus::kNonFinite);
  const GeometryTolerances& tol = ctx.tolerances;
  // Orientation: the caller's, else the direction of the samples.
  std::optional<Vec3> orientation = ctx.orientation;
  if (!orientation && (!ctx.previous.empty() || !ctx.next.empty())) {
    Vec3 a = ctx.previous.empty() ? problem.point(x) : problem.point(ctx.previous.back());
    Vec3 b = ctx.next.empty() ? problem.point(x) : problem.point(ctx.next.front());
    if ((b - a).norm() > 0) orientation = b - a;
  }
  const Vec3* o = orientation ? &*orientation : nullptr;
  GeometryContext oriented = ctx;
  oriented.orientation = orientation;
  switch (method) {
    case GeometryMethod::kExact: return exact_geometry(problem, x, o, tol);
    case GeometryMethod::kEstimate: return estimate_geometry(problem, x, EstimateCircle::kWuAndrade, oriented);
    case GeometryMethod::kBarnhillKersey: return estimate_geometry(problem, x, EstimateCircle::kThreePoint, oriented);
    case GeometryMethod::kWillmore: {
      auto l = surface_locals(problem, x, /*implicit_forms=*/true);
      if (!l) return with_status(problem.point(x), GeometryStatus::kNotApplicable);
      return willmore(std::get<ImplicitLocal>(l->first), std::get<ImplicitLocal>(l->second), o, tol);
    }
    default: break;
  }
  auto l = surface_locals(problem, x);
  if (!l) return with_status(problem.point(x), GeometryStatus::kNonFinite);
  const auto& [first, second] = *l;
  switch (method) {
    case GeometryMethod::kYeMaekawa: return ye_maekawa(first, second, o, tol);
    case GeometryMethod::kStoyanov: return stoyanov(first, second, o, tol);
    case GeometryMethod::kMixed: {
      // Thesis §3.2 and §4.3: Ye-Maekawa where sin(theta) >= 0.1.
      double sin_theta = unit_normal(first).cross(unit_normal(second)).norm();
      if (sin_theta >= tol.mixed_sin_theta) return ye_maekawa(first, second, o, tol);
      CurveGeometry e = estimate_geometry(problem, x, EstimateCircle::kWuAndrade, oriented);
      // Without samples the estimate has no curvature; Ye-Maekawa is then the better answer.
      if (e.status == GeometryStatus::kInsufficientSamples && !std::isfinite(e.kappa)) {
        CurveGeometry y = ye_maekawa(first, second, o, tol);
        if (std::isfinite(y.kappa)) return y;
      }
      return e;
    }
    default: break;
  }
  return with_status(problem.point(x), GeometryStatus::kNotApplicable);
}

std::optional<VecX> project_to_curve(const Problem& problem, const Vec3& X, const CurveSamplingOptions& opt) {
  auto guess = unknowns_near(problem, X);
  if (!guess) return std::nullopt;
  CorrectorOptions co;
  co.tolerance = opt.tolerance * problem.scale();
  co.max_iterations = opt.max_iterations;
  VecX x = *guess;
  // Already on the curve (a singular point included, where Newton has no update): keep it.
  if (problem.linearize(x).distance > co.tolerance) {
    CorrectorResult r = gauss_newton(problem, x, co);
    if (r.status != CorrectorStatus::kConverged && problem.linearize(r.x).distance > co.tolerance) return std::nullopt;
    x = r.x;
  }
  // Near a tangential point the residual is quadratic in the distance to the curve, so a residual
  // tolerance leaves the point up to sqrt(tolerance) off it. Gauss-Newton still converges there
  // (linearly), so keep stepping while the steps shrink, down to rounding.
  double last = std::numeric_limits<double>::infinity();
  for (int it = 0; it < 4 * opt.max_iterations; ++it) {
    Linearization L = problem.linearize(x);
    VecX dx = L.jacobian.completeOrthogonalDecomposition().solve(-L.h);
    double size = dx.norm();
    if (!dx.allFinite() || !(size < last)) break;
    x += dx;
    last = size;
    if (size <= 1e-15 * (1.0 + x.norm())) break;
  }
  return problem.wrap(x);
}

std::optional<VecX> step_along_curve(const Problem& problem, const VecX& x, const Vec3& t, double ds,
                                     const CurveSamplingOptions& opt) {
  const int n = problem.dim();
  const Vec3 target = problem.point(x) + ds * t;
  // Prediction: the tangent line, mapped to the unknowns by the least-squares inverse of D.
  Linearization L0 = problem.linearize(x);
  MatX A(n, n);
  VecX f(n);
  VecX xi = x + L0.point_jacobian.completeOrthogonalDecomposition().solve(ds * t);
  if (problem.kind() == PairKind::kParametricParametric) {
    // (p, q) of the second surface: its own least-squares inverse.
    auto l = surface_locals(problem, x);
    if (l) xi.tail(2) = x.tail(2) + tangent_coordinates(std::get<ParametricLocal>(l->second), ds * t);
  }
  const double tol = opt.tolerance * std::max(1.0, problem.point(x).norm());
  for (int it = 0; it < opt.max_iterations; ++it) {
    Linearization L = problem.linearize(xi);
    f.head(n - 1) = L.h;
    f[n - 1] = t.dot(L.point - target);
    A.topRows(n - 1) = L.jacobian;
    A.row(n - 1) = t.transpose() * L.point_jacobian;
    if (!f.allFinite() || !A.allFinite()) return std::nullopt;
    VecX dx = A.fullPivLu().solve(-f);
    if (!dx.allFinite()) return std::nullopt;
    xi += dx;
    // Converged: the update is already quadratically small; one more would change nothing the
    // estimate could see, except near singular points where the tangent amplifies position
    // errors by 1/sin(theta) -- hence the tight default tolerance.
    if (dx.norm() <= tol && L.distance <= tol) return problem.wrap(xi);
  }
  Linearization L = problem.linearize(xi);
  if (L.distance <= tol && std::fabs(t.dot(L.point - target)) <= tol) return problem.wrap(xi);
  return std::nullopt;
}

GeometryContext sample_context(const Problem& problem, const VecX& x, double step, const Vec3* orientation, int count,
                               const GeometryTolerances& tol) {
  GeometryContext ctx;
  ctx.tolerances = tol;
  auto l = surface_locals(problem, x);
  if (!l) return ctx;
  Vec3 t = intersection_tangent(l->first, l->second, orientation, tol);
  if (!t.allFinite()) return ctx;
  ctx.orientation = t;
  // Walk from x one chord at a time, re-taking the tangent at each new sample.
  auto walk = [&](double ds, int k, std::vector<VecX>* out) {
    VecX cur = x;
    Vec3 tc = t;
    for (int i = 0; i < k; ++i) {
      auto nxt = step_along_curve(problem, cur, tc, ds);
      if (!nxt) return;
      auto ln = surface_locals(problem, *nxt);
      if (!ln) return;
      Vec3 dir = ds > 0 ? Vec3(tc) : Vec3(-tc);
      Vec3 tn = intersection_tangent(ln->first, ln->second, &dir, tol);
      if (!tn.allFinite()) return;
      out->push_back(*nxt);
      cur = *nxt;
      tc = ds > 0 ? tn : Vec3(-tn);
    }
  };
  std::vector<VecX> back;
  walk(-step, count, &back);
  ctx.previous.assign(back.rbegin(), back.rend());
  walk(step, 1, &ctx.next);
  return ctx;
}

}  // namespace ssimarch
