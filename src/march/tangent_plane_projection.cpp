#include "ssimarch/march/tangent_plane_projection.hpp"

#include <cmath>
#include <limits>

#include "ssimarch/problem/singular_tolerances.hpp"

namespace ssimarch {

namespace {
// At most this many inner (foot-point) iterations per surface and round.
constexpr int kFootIterations = 12;

using J2 = Jet<2, 1>;
using J3 = Jet<3, 1>;

struct Foot {
  Vec3 point = Vec3::Zero();
  Vec3 normal = Vec3::Zero();  // unit
  Vec2 uv = Vec2::Zero();      // parametric surfaces only
};

// Gauss-Newton on |S(u,v) - X|^2 from uv; the foot is extrapolated linearly over the last
// update (second order small), so no extra evaluation is spent on it.
Foot parametric_foot(const Surface& s, Vec2 uv, const Vec3& X, double stop, long* evaluations) {
  Foot f;
  for (int it = 0; it < kFootIterations; ++it) {
    Vec3T<J2> p = s.point(J2::variable(0, uv[0]), J2::variable(1, uv[1]));
    ++*evaluations;
    Eigen::Matrix<double, 3, 2> D;
    Vec3 q;
    for (int i = 0; i < 3; ++i) {
      q[i] = p[i].value();
      D(i, 0) = p[i].d(0);
      D(i, 1) = p[i].d(1);
    }
    Vec2 du = D.completeOrthogonalDecomposition().solve(X - q);
    Vec3 n = D.col(0).cross(D.col(1));
    f.normal = n.norm() > 0 ? Vec3(n.normalized()) : Vec3::Zero();
    if (!du.allFinite()) {
      f.point = q;
      f.uv = uv;
      break;
    }
    uv += du;
    f.uv = uv;
    f.point = q + D * du;
    if ((D * du).norm() <= stop) break;
  }
  return f;
}

// Newton projection onto f = 0 along the gradient.
Foot implicit_foot(const Surface& s, Vec3 X, double stop, long* evaluations) {
  Foot f;
  for (int it = 0; it < kFootIterations; ++it) {
    J3 v = s.value(Vec3T<J3>(J3::variable(0, X.x()), J3::variable(1, X.y()), J3::variable(2, X.z())));
    ++*evaluations;
    Vec3 g(v.d(0), v.d(1), v.d(2));
    double g2 = g.squaredNorm();
    if (!(g2 > 0) || !std::isfinite(v.value())) break;
    f.normal = g / std::sqrt(g2);
    Vec3 step = -v.value() / g2 * g;
    X += step;
    if (step.norm() <= stop) break;
  }
  f.point = X;
  return f;
}

// The feet of a point on both surfaces, remembering the parameters of the last feet as the
// starting guesses of the next round and as the round's unknowns.
struct FootPair {
  FootPair(const Problem& p, double s) : problem(p), stop(s) {}
  const Problem& problem;
  double stop;
  Vec2 uv = Vec2::Zero(), pq = Vec2::Zero();
  Foot A, B;

  void find(const Vec3& X, std::array<long, 2>* evaluations) {
    switch (problem.kind()) {
      case PairKind::kParametricParametric:
        A = parametric_foot(problem.first(), uv, X, stop, &(*evaluations)[0]);
        B = parametric_foot(problem.second(), pq, X, stop, &(*evaluations)[1]);
        uv = A.uv;
        pq = B.uv;
        break;
      case PairKind::kParametricImplicit:
        A = parametric_foot(problem.first(), uv, X, stop, &(*evaluations)[0]);
        B = implicit_foot(problem.second(), X, stop, &(*evaluations)[1]);
        uv = A.uv;
        break;
      case PairKind::kImplicitImplicit:
        A = implicit_foot(problem.first(), X, stop, &(*evaluations)[0]);
        B = implicit_foot(problem.second(), X, stop, &(*evaluations)[1]);
        break;
    }
  }
  UnknownVec unknowns(const Vec3& P) const {
    UnknownVec x(problem.dim());
    switch (problem.kind()) {
      case PairKind::kParametricParametric: x << uv[0], uv[1], pq[0], pq[1]; break;
      case PairKind::kParametricImplicit: x << uv[0], uv[1]; break;
      case PairKind::kImplicitImplicit: x = P; break;
    }
    return x;
  }
};

// P0 of the guess: the mean of its surface points (the point itself, implicit-implicit).
Vec3 starting_point(const Problem& problem, const UnknownVec& guess, FootPair* feet, std::array<long, 2>* evaluations) {
  switch (problem.kind()) {
    case PairKind::kParametricParametric: {
      feet->uv = guess.head(2);
      feet->pq = guess.tail(2);
      Vec3T<double> a = problem.first().point(feet->uv[0], feet->uv[1]), b = problem.second().point(feet->pq[0], feet->pq[1]);
      *evaluations = {1, 1};
      return 0.5 * (Vec3(a.x, a.y, a.z) + Vec3(b.x, b.y, b.z));
    }
    case PairKind::kParametricImplicit: {
      feet->uv = guess.head(2);
      Vec3T<double> a = problem.first().point(feet->uv[0], feet->uv[1]);
      *evaluations = {1, 0};
      return Vec3(a.x, a.y, a.z);
    }
    case PairKind::kImplicitImplicit: break;
  }
  return guess;
}

// Seed 000 §2, one round: the midpoint of the projections of A and B onto the line where their
// tangent planes meet (direction d = n_A x n_B, its point in span(n_A, n_B) nearest to P).
Vec3 midpoint_on_plane_line(const Foot& A, const Foot& B, const Vec3& P, const Vec3& d) {
  Eigen::Matrix<double, 2, 3> N;
  N.row(0) = A.normal.transpose();
  N.row(1) = B.normal.transpose();
  const Eigen::Vector2d rhs(A.normal.dot(A.point - P), B.normal.dot(B.point - P));
  const Vec3 X0 = P + N.transpose() * (N * N.transpose()).ldlt().solve(rhs);
  const Vec3 e = d.normalized();
  const Vec3 O1 = X0 + (A.point - X0).dot(e) * e, O2 = X0 + (B.point - X0).dot(e) * e;
  return 0.5 * (O1 + O2);
}

}  // namespace

CorrectorResult TangentPlaneProjection::correct(const Problem& problem, const UnknownVec& guess,
                                                const CorrectorOptions& options) const {
  CorrectorResult r;
  r.x = guess;
  FootPair feet(problem, 0.1 * options.tolerance);
  Vec3 P = starting_point(problem, guess, &feet, &r.evaluations);
  feet.find(P, &r.evaluations);
  ConvergenceRule rule(std::numeric_limits<double>::infinity());
  for (int it = 1; it <= options.max_iterations; ++it) {
    const Vec3 d = feet.A.normal.cross(feet.B.normal);
    if (!(d.norm() > kParallelPlanesSinTheta)) {
      r.status = CorrectorStatus::kSingular;
      return r;
    }
    P = midpoint_on_plane_line(feet.A, feet.B, P, d);
    r.iterations = it;
    if (!P.allFinite()) break;
    feet.find(P, &r.evaluations);
    r.x = feet.unknowns(P);
    const ConvergenceRule::Verdict v = rule.judge(problem.linearize(r.x), options, &r);
    if (v == ConvergenceRule::Verdict::kConverged) return r;
    if (v == ConvergenceRule::Verdict::kDiverging) break;
  }
  r.status = CorrectorStatus::kDiverged;
  return r;
}

}  // namespace ssimarch
