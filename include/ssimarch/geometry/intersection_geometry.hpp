// The differential geometry of the intersection curve of a Problem at a point x of it, by any
// method of issue 4 (docs/geometry.md): the entry point for the tracer's `--geometry METHOD`
// and for `ssimarch curve-geometry`.
//
// Compiled into ssimarch_geometry, which links ssimarch_march (the march library does not link
// geometry, so there is no cycle).
#pragma once

#include <optional>
#include <vector>

#include "ssimarch/geometry/curve_geometry.hpp"
#include "ssimarch/geometry/estimate.hpp"
#include "ssimarch/geometry/surface_local.hpp"
#include "ssimarch/problem/problem.hpp"

namespace ssimarch {

/// What a method may use besides the point itself.
struct GeometryContext {
  /// Solutions of the problem traced before x, oldest first (the estimate uses the last two or
  /// three; the closed-form methods ignore them).
  std::vector<VecX> previous;
  /// Solutions after x, nearest first (the thesis' forward neighbour; optional). Without one
  /// the estimate is the thesis' estimate at the previous sample (one sample behind; see
  /// docs/geometry.md), reported with x's own point, t and theta.
  std::vector<VecX> next;
  /// Orients t: t . orientation >= 0. Without it: the direction of the samples (previous ->
  /// next) when there are any, else the method's natural orientation.
  std::optional<Vec3> orientation;
  GeometryTolerances tolerances;
};

/// t, n, b, kappa, tau, kappa', theta of the problem's curve at the solution x by `method`.
/// x must be on the curve (corrected); see project_to_curve for an arbitrary 3D point.
/// Never throws for numeric trouble: the status says what was determined (curve_geometry.hpp).
CurveGeometry evaluate_geometry(const Problem& problem, const VecX& x, GeometryMethod method,
                                const GeometryContext& ctx = {});

/// Derivative data of the two surfaces at x, in the forms the pair kind uses (parametric at
/// (u,v) / (p,q), implicit at point(x)); with `implicit_forms`, both implicit forms at point(x)
/// (empty if a surface has none).
std::optional<std::pair<SurfaceLocal, SurfaceLocal>> surface_locals(const Problem& problem, const VecX& x,
                                                                     bool implicit_forms = false);

/// `exact`: the curve's arc-length jet by the implicit function theorem (curve_jet.hpp, order 3)
/// through frenet_from_derivatives. kSingular where the curve Jacobian is rank deficient or
/// sin(theta) < tol.singular_sin_theta.
CurveGeometry exact_geometry(const Problem& problem, const VecX& x, const Vec3* orientation,
                             const GeometryTolerances& tol = {});

/// Bounds of project_to_curve and step_along_curve.
struct CurveSamplingOptions {
  /// Newton stops when the distance to both surfaces and the last update are below
  /// tolerance * max(1, |point|) (model units).
  double tolerance = 1e-14;
  int max_iterations = 30;
};

/// The solution nearest to a 3D point: unknowns_near + minimum-norm Newton (march/corrector.hpp).
/// Empty when Newton does not converge.
std::optional<VecX> project_to_curve(const Problem& problem, const Vec3& X, const CurveSamplingOptions& opt = {});

/// The solution of H = 0 on the plane t . (point - (P + ds t)) = 0, P = point(x), by Newton on
/// that square system from the tangent-line prediction: the point of x's branch one chord ds
/// further along t (ds < 0: backwards). Works at singular points too, because the plane cuts
/// the branches apart. Empty when Newton does not converge.
std::optional<VecX> step_along_curve(const Problem& problem, const VecX& x, const Vec3& t, double ds,
                                     const CurveSamplingOptions& opt = {});

/// A context for the estimate at x from samples `count` back and one ahead, `step` model units
/// apart along the curve (t from `orientation`, or the natural transversal orientation).
/// Samples that cannot be computed are left out (the estimate then reports fewer samples).
GeometryContext sample_context(const Problem& problem, const VecX& x, double step, const Vec3* orientation,
                               int count = 2, const GeometryTolerances& tol = {});

}  // namespace ssimarch
