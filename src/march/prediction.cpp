#include "ssimarch/march/prediction.hpp"

namespace ssimarch {

namespace {

// At most this many Gauss-Newton foot-point iterations per surface in map_to_unknowns.
constexpr int kMapIterations = 8;

using J2 = Jet<2, 1>;

struct SurfacePatch {
  Vec3 p;
  Eigen::Matrix<double, 3, 2> d;
};
SurfacePatch eval_patch(const Surface& s, const Vec2& uv) {
  Vec3T<J2> f = s.point(J2::variable(0, uv[0]), J2::variable(1, uv[1]));
  SurfacePatch r;
  for (int i = 0; i < 3; ++i) {
    r.p[i] = f[i].value();
    r.d(i, 0) = f[i].d(0);
    r.d(i, 1) = f[i].d(1);
  }
  return r;
}

// Foot of Q on a parametric surface by Gauss-Newton from uv (the first iteration is the
// first-order map through the pseudo-inverse of [S_u S_v]).
Vec2 foot_point(const Surface& s, Vec2 uv, const Vec3& Q, double stop, long* evaluations) {
  for (int it = 0; it < kMapIterations; ++it) {
    SurfacePatch f = eval_patch(s, uv);
    ++*evaluations;
    if (!f.p.allFinite() || !f.d.allFinite()) break;
    Vec2 du = f.d.completeOrthogonalDecomposition().solve(Q - f.p);
    if (!du.allFinite()) break;
    uv += du;
    if ((f.d * du).norm() <= stop) break;
  }
  return uv;
}

}  // namespace

UnknownVec map_to_unknowns(const Problem& problem, const UnknownVec& x0, const Vec3& Q, double stop, std::array<long, 2>* evaluations) {
  UnknownVec x = x0;
  switch (problem.kind()) {
    case PairKind::kImplicitImplicit:
      x = Q;
      break;
    case PairKind::kParametricImplicit:
      x.head(2) = foot_point(problem.first(), x0.head(2), Q, stop, &(*evaluations)[0]);
      break;
    case PairKind::kParametricParametric:
      x.head(2) = foot_point(problem.first(), x0.head(2), Q, stop, &(*evaluations)[0]);
      x.tail(2) = foot_point(problem.second(), x0.tail(2), Q, stop, &(*evaluations)[1]);
      break;
  }
  return x;
}

namespace internal {

Prediction tangent_step(const Problem& problem, const MarchState& s, double h) {
  Prediction r;
  r.x = s.here.x[0] + h * s.here.x[1];
  r.point = problem.point(r.x);
  if (problem.kind() != PairKind::kImplicitImplicit) ++r.evaluations[0];
  r.arc = h;
  return r;
}

Prediction fallback_step(const Problem& problem, const MarchState& s, double h) {
  Prediction r = tangent_step(problem, s, h);
  r.fallback = true;
  return r;
}

Prediction prediction_at(const Problem& problem, const MarchState& s, const Vec3& Q, double arc) {
  Prediction r;
  r.point = Q;
  r.arc = arc;
  r.x = map_to_unknowns(problem, s.here.x[0], Q, s.map_tolerance, &r.evaluations);
  return r;
}

}  // namespace internal

}  // namespace ssimarch
