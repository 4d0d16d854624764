// Private to singular/: the charts the local curve is built on (local_curve.cpp,
// collapsed_row_chart.cpp; docs/math/singular_local_curve.md §1 and §6).
#pragma once

#include <functional>

#include "ssimarch/problem/problem.hpp"
#include "ssimarch/singular/local_curve.hpp"

namespace ssimarch::local_charts {

LocalJet dot_jet(const Vec3T<LocalJet>& a, const Vec3& e);

/// F, F_u, F_v of a parametric surface at (u, v).
struct FirstOrder {
  Vec3 p, du, dv;
};
FirstOrder parametric_first_order(const Surface& s, double u, double v);

/// grad f at p (and f(p) into `value` where given).
Vec3 implicit_gradient(const Surface& s, const Vec3& p, double* value);

/// |Hess f(p)| (Frobenius), the scale of f where its gradient vanishes.
double implicit_hessian_norm(const Surface& s, const Vec3& p);

/// Orthonormal tangent frame (e1, e2) with e1 x e2 = n, e1 along `hint` where it is not parallel to n.
void frame_from_normal(const Vec3& n, const Vec3& hint, Vec3* e1, Vec3* e2);

/// How far a parametric chart is from degenerate: |F_u x F_v| / (|F_u|^2 + |F_v|^2) in [0, 1/2], with
/// F_u and F_v per the width of their parameter ranges (independent of the parameters' units).
double chart_condition(const Surface& s, double u, double v);

/// The unit dividing an implicit surface's value into model units over a chart: its gradient's
/// length, floored where the surface is singular (kSingularSurfaceGradientRatio).
double implicit_unit(const Surface& g, const Vec3& p, double scale);

/// F over its tangent plane at (u0, v0): (u, v) = (u0, v0) + M^-1 (s, t); sets origin, frame and
/// unknowns {U, V} of `c`, and F(U, V) into Fj. False where F_u x F_v = 0.
bool parametric_chart(const Surface& F, double u0, double v0, LocalCurve* c, Vec3T<LocalJet>* Fj);

/// The implicit surface `chart` over its tangent plane at its point nearest P0: origin, frame
/// of `c`, P(s, t) = P0 + s e1 + t e2 + w(s, t) N into Pj and |grad f| there. False where the
/// gradient vanishes.
bool implicit_graph(const Surface& chart, Vec3 P0, LocalCurve* c, Vec3T<LocalJet>* Pj, double* gradient);

/// The nearest parameters of the pair's first and/or second parametric surface at a 3D point,
/// replacing their entries of the unknowns (LocalCurve::lift).
std::function<VecX(const Vec3&, VecX)> lift_parameters(const Problem& pr, bool first, bool second);

}  // namespace ssimarch::local_charts
