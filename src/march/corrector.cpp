#include "ssimarch/march/corrector.hpp"

#include <cmath>
#include <limits>

namespace ssimarch {

std::string_view to_string(CorrectorStatus s) {
  switch (s) {
    case CorrectorStatus::kConverged: return "converged";
    case CorrectorStatus::kDiverged: return "diverged";
    case CorrectorStatus::kSingular: return "singular";
  }
  return "?";
}

namespace {
// Relative singular value below which J_H has no usable pseudo-inverse.
constexpr double kSingularRatio = 1e-14;
// Projection corrector: tangent planes with |n_F x n_G| <= kParallelPlanes have no line.
constexpr double kParallelPlanes = 1e-14;
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
enum class Progress { kConverged, kContinue, kDiverging };

// After an update: counts the linearization L at the new point and judges it. Converged when
// its distance is <= tolerance; diverging when the distance is not finite or grew twice in a
// row (the CorrectorStatus::kDiverged conditions); both correctors share this rule.
Progress assess(const Linearization& L, const CorrectorOptions& options, CorrectorResult* r, double* previous, int* growth) {
  ++r->linearizations;
  ++r->evaluations[0];
  ++r->evaluations[1];
  r->distance = L.distance;
  if (!std::isfinite(L.distance)) return Progress::kDiverging;
  if (L.distance <= options.tolerance) {
    r->status = CorrectorStatus::kConverged;
    return Progress::kConverged;
  }
  *growth = L.distance > *previous ? *growth + 1 : 0;
  if (*growth >= 2) return Progress::kDiverging;
  *previous = L.distance;
  return Progress::kContinue;
}
}  // namespace

CorrectorResult NewtonCorrector::correct(const Problem& problem, const VecX& guess,
                                         const CorrectorOptions& options) const {
  CorrectorResult r;
  r.x = guess;
  Linearization L = problem.linearize(r.x);
  ++r.linearizations;
  r.evaluations = {1, 1};
  double previous = L.distance;
  int growth = 0;
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (!L.h.allFinite() || !L.jacobian.allFinite()) {
      r.status = CorrectorStatus::kDiverged;
      r.distance = L.distance;
      return r;
    }
    Eigen::JacobiSVD<MatX> svd(L.jacobian, Eigen::ComputeThinU | Eigen::ComputeThinV);
    if (Problem::rank_ratio(L) <= kSingularRatio) {
      r.status = CorrectorStatus::kSingular;
      r.distance = L.distance;
      return r;
    }
    r.x -= svd.solve(L.h);
    r.iterations = it;
    L = problem.linearize(r.x);
    const Progress p = assess(L, options, &r, &previous, &growth);
    if (p == Progress::kConverged) return r;
    if (p == Progress::kDiverging) break;
  }
  r.status = CorrectorStatus::kDiverged;
  return r;
}

CorrectorResult ProjectionCorrector::correct(const Problem& problem, const VecX& guess,
                                             const CorrectorOptions& options) const {
  CorrectorResult r;
  r.x = guess;
  const PairKind kind = problem.kind();
  const double stop = 0.1 * options.tolerance;
  Vec2 uv = Vec2::Zero(), pq = Vec2::Zero();
  Vec3 P;
  switch (kind) {
    case PairKind::kParametricParametric: {
      uv = guess.head(2);
      pq = guess.tail(2);
      Vec3T<double> a = problem.first().point(uv[0], uv[1]), b = problem.second().point(pq[0], pq[1]);
      P = 0.5 * (Vec3(a.x, a.y, a.z) + Vec3(b.x, b.y, b.z));
      r.evaluations = {1, 1};
      break;
    }
    case PairKind::kParametricImplicit: {
      uv = guess.head(2);
      Vec3T<double> a = problem.first().point(uv[0], uv[1]);
      P = Vec3(a.x, a.y, a.z);
      r.evaluations = {1, 0};
      break;
    }
    case PairKind::kImplicitImplicit:
      P = guess;
      break;
  }
  auto feet = [&](const Vec3& X, Foot* A, Foot* B) {
    switch (kind) {
      case PairKind::kParametricParametric:
        *A = parametric_foot(problem.first(), uv, X, stop, &r.evaluations[0]);
        *B = parametric_foot(problem.second(), pq, X, stop, &r.evaluations[1]);
        uv = A->uv;
        pq = B->uv;
        break;
      case PairKind::kParametricImplicit:
        *A = parametric_foot(problem.first(), uv, X, stop, &r.evaluations[0]);
        *B = implicit_foot(problem.second(), X, stop, &r.evaluations[1]);
        uv = A->uv;
        break;
      case PairKind::kImplicitImplicit:
        *A = implicit_foot(problem.first(), X, stop, &r.evaluations[0]);
        *B = implicit_foot(problem.second(), X, stop, &r.evaluations[1]);
        break;
    }
  };
  Foot A, B;
  feet(P, &A, &B);
  double previous = std::numeric_limits<double>::infinity();
  int growth = 0;
  for (int it = 1; it <= options.max_iterations; ++it) {
    const Vec3 d = A.normal.cross(B.normal);
    if (!(d.norm() > kParallelPlanes)) {
      r.status = CorrectorStatus::kSingular;
      return r;
    }
    // The line of the tangent planes n_A.X = n_A.A, n_B.X = n_B.B: its point in span(n_A, n_B)
    // (the minimum-norm solution), direction d.
    Eigen::Matrix<double, 2, 3> N;
    N.row(0) = A.normal.transpose();
    N.row(1) = B.normal.transpose();
    const Eigen::Vector2d rhs(A.normal.dot(A.point - P), B.normal.dot(B.point - P));
    const Vec3 X0 = P + N.transpose() * (N * N.transpose()).ldlt().solve(rhs);
    const Vec3 e = d.normalized();
    const Vec3 O1 = X0 + (A.point - X0).dot(e) * e, O2 = X0 + (B.point - X0).dot(e) * e;
    P = 0.5 * (O1 + O2);
    r.iterations = it;
    if (!P.allFinite()) break;
    feet(P, &A, &B);
    switch (kind) {
      case PairKind::kParametricParametric: r.x << uv[0], uv[1], pq[0], pq[1]; break;
      case PairKind::kParametricImplicit: r.x << uv[0], uv[1]; break;
      case PairKind::kImplicitImplicit: r.x = P; break;
    }
    const Progress p = assess(problem.linearize(r.x), options, &r, &previous, &growth);
    if (p == Progress::kConverged) return r;
    if (p == Progress::kDiverging) break;
  }
  r.status = CorrectorStatus::kDiverged;
  return r;
}

AnyCorrector make_corrector(const TraceOptions& options) {
  if (options.corrector == CorrectorKind::kProjection) return ProjectionCorrector{};
  return NewtonCorrector{};
}

CorrectorResult correct(const AnyCorrector& c, const Problem& problem, const VecX& guess, const CorrectorOptions& options) {
  return std::visit([&](const auto& x) { return x.correct(problem, guess, options); }, c);
}

CorrectorResult solve_with_fixed_unknown(const Problem& problem, const VecX& guess, int i, double value,
                                         const CorrectorOptions& options) {
  CorrectorResult r;
  r.x = guess;
  r.x[i] = value;
  const int n = problem.dim();
  for (int it = 1; it <= options.max_iterations; ++it) {
    Linearization L = problem.linearize(r.x);
    ++r.linearizations;
    ++r.evaluations[0];
    ++r.evaluations[1];
    r.distance = L.distance;
    if (!L.h.allFinite() || !L.jacobian.allFinite()) break;
    if (L.distance <= options.tolerance && it > 1) {
      r.status = CorrectorStatus::kConverged;
      return r;
    }
    MatX A(n, n);
    A.topRows(n - 1) = L.jacobian;
    A.row(n - 1).setZero();
    A(n - 1, i) = 1.0;
    VecX rhs(n);
    rhs.head(n - 1) = L.h;
    rhs[n - 1] = r.x[i] - value;
    Eigen::FullPivLU<MatX> lu(A);
    if (!lu.isInvertible()) {
      r.status = CorrectorStatus::kSingular;
      return r;
    }
    r.x -= lu.solve(rhs);
    r.iterations = it;
  }
  Linearization L = problem.linearize(r.x);
  ++r.linearizations;
  ++r.evaluations[0];
  ++r.evaluations[1];
  r.distance = L.distance;
  r.status = L.distance <= options.tolerance ? CorrectorStatus::kConverged : CorrectorStatus::kDiverged;
  return r;
}

}  // namespace ssimarch
