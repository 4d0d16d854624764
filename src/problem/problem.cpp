#include "ssimarch/problem/problem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/core/error.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"
#include "ssimarch/surface/unbounded.hpp"

namespace ssimarch {

std::string_view to_string(PairKind kind) {
  switch (kind) {
    case PairKind::kParametricParametric: return "parametric-parametric";
    case PairKind::kParametricImplicit: return "parametric-implicit";
    case PairKind::kImplicitImplicit: return "implicit-implicit";
  }
  return "?";
}

namespace {

using J2 = Jet<2, 1>;
using J3 = Jet<3, 1>;

struct ParametricFirstOrder {
  Vec3 p, fu, fv;
};
ParametricFirstOrder parametric_first_order(const Surface& s, double u, double v) {
  Vec3T<J2> f = s.point(J2::variable(0, u), J2::variable(1, v));
  ParametricFirstOrder r;
  for (int i = 0; i < 3; ++i) {
    r.p[i] = f[i].value();
    r.fu[i] = f[i].d(0);
    r.fv[i] = f[i].d(1);
  }
  return r;
}

struct ImplicitFirstOrder {
  double value;
  Vec3 grad;
};
ImplicitFirstOrder implicit_first_order(const Surface& s, const Vec3& p) {
  Vec3T<J3> x(J3::variable(0, p.x()), J3::variable(1, p.y()), J3::variable(2, p.z()));
  J3 f = s.value(x);
  return {f.value(), Vec3(f.d(0), f.d(1), f.d(2))};
}

Vec3 unit_or_zero(const Vec3& v) {
  double n = v.norm();
  return n > 0 ? Vec3(v / n) : Vec3::Zero();
}

// 3D bounding box diagonal of a parametric surface, from a coarse grid of its domain.
double parametric_extent(const Surface& s) {
  const ParamDomain& d = s.domain();
  Vec3 lo = Vec3::Constant(std::numeric_limits<double>::infinity()), hi = -lo;
  const int n = 12;
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) {
      double u = d.u.lo + (d.u.hi - d.u.lo) * i / n, v = d.v.lo + (d.v.hi - d.v.lo) * j / n;
      Vec3T<double> p = s.point(u, v);
      Vec3 q(p.x, p.y, p.z);
      if (!q.allFinite()) continue;
      lo = lo.cwiseMin(q);
      hi = hi.cwiseMax(q);
    }
  double e = (hi - lo).norm();
  if (e == 0) e = (hi - lo).stableNorm();  // a tiny model's squares underflow: its size, not 1
  return std::isfinite(e) && e > 0 ? e : 1.0;
}

// A surface unbounded in a direction is clipped to the other surface's box, or both to a stated
// box when both are unbounded (surface/unbounded.hpp; issue 29: a default must never cut the
// intersection). Bounded surfaces, the common case, are left as they are (no copy).
void bound_unbounded(Surface* a, Surface* b) {
  const bool ua = has_unbounded_direction(*a), ub = has_unbounded_direction(*b);
  if (ua && ub) {
    const Box region = unbounded_pair_region(*a, *b);
    *a = clipped_to(*a, region);
    *b = clipped_to(*b, region);
  } else if (ua) {
    *a = clipped_to(*a, b->box());
  } else if (ub) {
    *b = clipped_to(*b, a->box());
  }
}

// Whether the surface lies inside its box() for certain: a primitive's box holds its (trimmed)
// shape, a patch's is the box of its control points (a B-spline or Bezier patch with positive
// weights lies in their convex hull). A parametric expression's box is sampled, and an implicit
// expression's is where its zero set is looked for, not a bound the pair's curves keep to.
bool box_holds_surface(const Surface& s) { return !s.get_if<ExprParametric>() && !s.get_if<ExprImplicit>(); }

bool boxes_overlap(const Box& a, const Box& b) {
  return a.x.lo <= b.x.hi && b.x.lo <= a.x.hi && a.y.lo <= b.y.hi && b.y.lo <= a.y.hi && a.z.lo <= b.z.hi &&
         b.z.lo <= a.z.hi;
}

}  // namespace

Problem::Problem(Surface first, Surface second, PairKind kind)
    : first_(std::move(first)), second_(std::move(second)), kind_(kind) {
  bound_unbounded(&first_, &second_);
  switch (kind_) {
    case PairKind::kParametricParametric: {
      if (!first_.is_parametric() || !second_.is_parametric())
        throw InputError("", "a parametric-parametric intersection needs two surfaces with a parametric form");
      dim_ = 4;
      for (const Surface* s : {&first_, &second_}) {
        const ParamDomain& d = s->domain();
        bounds_.push_back(d.u);
        bounds_.push_back(d.v);
        periods_.push_back(d.periodic_u || closes_seam(*s, 0) ? d.u.hi - d.u.lo : 0.0);
        periods_.push_back(d.periodic_v || closes_seam(*s, 1) ? d.v.hi - d.v.lo : 0.0);
      }
      scale_ = std::min(parametric_extent(first_), parametric_extent(second_));
      break;
    }
    case PairKind::kParametricImplicit: {
      if (!first_.is_parametric() || !second_.is_implicit())
        throw InputError("", "a parametric-implicit intersection needs a parametric first surface and an implicit second surface");
      dim_ = 2;
      const ParamDomain& d = first_.domain();
      bounds_ = {d.u, d.v};
      periods_ = {d.periodic_u || closes_seam(first_, 0) ? d.u.hi - d.u.lo : 0.0,
                  d.periodic_v || closes_seam(first_, 1) ? d.v.hi - d.v.lo : 0.0};
      scale_ = parametric_extent(first_);
      break;
    }
    case PairKind::kImplicitImplicit: {
      if (!first_.is_implicit() || !second_.is_implicit())
        throw InputError("", "an implicit-implicit intersection needs two surfaces with an implicit form");
      dim_ = 3;
      const Box &a = first_.box(), &b = second_.box();
      bounds_ = {Interval{std::max(a.x.lo, b.x.lo), std::min(a.x.hi, b.x.hi)},
                 Interval{std::max(a.y.lo, b.y.lo), std::min(a.y.hi, b.y.hi)},
                 Interval{std::max(a.z.lo, b.z.lo), std::min(a.z.hi, b.z.hi)}};
      for (const Interval& i : bounds_)
        if (!(i.lo < i.hi)) disjoint_ = true;  // no intersection: a result, not an error (issue 11)
      periods_ = {0.0, 0.0, 0.0};
      scale_ = Vec3(bounds_[0].hi - bounds_[0].lo, bounds_[1].hi - bounds_[1].lo, bounds_[2].hi - bounds_[2].lo).norm();
      break;
    }
  }
  // Surfaces whose boxes bound them and do not overlap cannot meet, whatever their unknowns
  // (issue 28: a B-spline face of a model against a far one searched 26,424 boxes in 46 s).
  if (box_holds_surface(first_) && box_holds_surface(second_) && !boxes_overlap(first_.box(), second_.box()))
    disjoint_ = true;
  trims_ = problem_trims(*this);
}

Vec3 Problem::point(const UnknownVec& x) const {
  Vec3T<double> p = point(x.data());
  return {p.x, p.y, p.z};
}

Linearization Problem::linearize(const UnknownVec& x) const {
  Linearization L;
  const int m = num_equations();
  L.h.resize(m);
  L.jacobian.setZero(m, dim_);
  L.point_jacobian.setZero(3, dim_);
  switch (kind_) {
    case PairKind::kParametricParametric: {
      ParametricFirstOrder a = parametric_first_order(first_, x[0], x[1]);
      ParametricFirstOrder b = parametric_first_order(second_, x[2], x[3]);
      L.h = a.p - b.p;
      L.jacobian.col(0) = a.fu;
      L.jacobian.col(1) = a.fv;
      L.jacobian.col(2) = -b.fu;
      L.jacobian.col(3) = -b.fv;
      L.point = a.p;
      L.point_jacobian.col(0) = a.fu;
      L.point_jacobian.col(1) = a.fv;
      L.normal_first = unit_or_zero(a.fu.cross(a.fv));
      L.normal_second = unit_or_zero(b.fu.cross(b.fv));
      L.distance = L.h.norm();
      break;
    }
    case PairKind::kParametricImplicit: {
      ParametricFirstOrder a = parametric_first_order(first_, x[0], x[1]);
      ImplicitFirstOrder g = implicit_first_order(second_, a.p);
      double gn = g.grad.norm();
      double scale = gn > 0 ? 1.0 / gn : 1.0;
      L.h[0] = g.value * scale;
      L.jacobian(0, 0) = g.grad.dot(a.fu) * scale;
      L.jacobian(0, 1) = g.grad.dot(a.fv) * scale;
      L.point = a.p;
      L.point_jacobian.col(0) = a.fu;
      L.point_jacobian.col(1) = a.fv;
      L.normal_first = unit_or_zero(a.fu.cross(a.fv));
      L.normal_second = unit_or_zero(g.grad);
      L.distance = gn > 0 ? std::fabs(L.h[0]) : std::numeric_limits<double>::infinity();
      if (gn == 0 && g.value == 0) L.distance = 0;
      break;
    }
    case PairKind::kImplicitImplicit: {
      Vec3 p(x[0], x[1], x[2]);
      ImplicitFirstOrder f = implicit_first_order(first_, p);
      ImplicitFirstOrder g = implicit_first_order(second_, p);
      double fn = f.grad.norm(), gn = g.grad.norm();
      L.h[0] = fn > 0 ? f.value / fn : f.value;
      L.h[1] = gn > 0 ? g.value / gn : g.value;
      L.jacobian.row(0) = (fn > 0 ? f.grad / fn : f.grad).transpose();
      L.jacobian.row(1) = (gn > 0 ? g.grad / gn : g.grad).transpose();
      L.point = p;
      L.point_jacobian = PointJacobian::Identity(3, 3);
      L.normal_first = unit_or_zero(f.grad);
      L.normal_second = unit_or_zero(g.grad);
      auto dist = [](double v, double n) {
        return n > 0 ? std::fabs(v) / n : (v == 0 ? 0.0 : std::numeric_limits<double>::infinity());
      };
      L.distance = std::max(dist(f.value, fn), dist(g.value, gn));
      break;
    }
  }
  return L;
}

double Problem::rank_ratio(const Linearization& L) {
  if (!L.jacobian.allFinite()) return 0.0;
  if (L.jacobian.rows() == 1) {
    Eigen::JacobiSVD<PointJacobian> svd(L.point_jacobian);
    double smax = svd.singularValues()[0];
    return smax > 0 ? std::min(1.0, L.jacobian.norm() / smax) : 0.0;
  }
  Eigen::JacobiSVD<EquationJacobian> svd(L.jacobian);
  return rank_ratio(svd.singularValues());
}

double Problem::rank_ratio(const Eigen::Ref<const Eigen::VectorXd>& singular_values) {
  const auto& sv = singular_values;
  return sv[0] > 0 ? sv[sv.size() - 1] / sv[0] : 0.0;
}

UnknownVec Problem::wrap(const UnknownVec& x) const {
  UnknownVec y = x;
  for (int i = 0; i < dim_; ++i) {
    double P = periods_[static_cast<std::size_t>(i)];
    if (P > 0) {
      double lo = bounds_[static_cast<std::size_t>(i)].lo;
      y[i] = lo + (y[i] - lo) - P * std::floor((y[i] - lo) / P);
    }
  }
  return y;
}

UnknownVec Problem::difference(const UnknownVec& a, const UnknownVec& b) const {
  UnknownVec d = b - a;
  for (int i = 0; i < dim_; ++i) {
    double P = periods_[static_cast<std::size_t>(i)];
    if (P > 0) d[i] -= P * std::round(d[i] / P);
  }
  return d;
}

bool Problem::inside(const UnknownVec& x, double eps) const {
  for (int i = 0; i < dim_; ++i) {
    if (periods_[static_cast<std::size_t>(i)] > 0) continue;
    const Interval& b = bounds_[static_cast<std::size_t>(i)];
    if (!(x[i] >= b.lo - eps && x[i] <= b.hi + eps)) return false;
  }
  // The trims of implicit forms bound the curve as the parameter domains do (docs/math/poles.md §2).
  if (kind_ == PairKind::kParametricParametric || trims_.empty()) return true;
  const Vec3 p = point(x);
  for (const Slab& t : trims_)
    if (!t.contains(p, eps)) return false;
  return true;
}

std::vector<std::string> Problem::unknown_names() const {
  switch (kind_) {
    case PairKind::kParametricParametric: return {"u", "v", "p", "q"};
    case PairKind::kParametricImplicit: return {"u", "v"};
    case PairKind::kImplicitImplicit: return {"x", "y", "z"};
  }
  return {};
}

}  // namespace ssimarch
