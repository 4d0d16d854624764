#include "ssimarch/topology/singular_registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/topology/tangential_contact.hpp"

namespace ssimarch {

int SingularRegistry::add(const SingularLocation& s) {
  for (std::size_t i = 0; i < nodes_.size(); ++i)
    if ((nodes_[i].location.point - s.point).norm() <= merge_) return static_cast<int>(i);
  SingularNode n;
  n.location = s;
  n.location.x = problem_.wrap(s.x);
  n.curve = local_curve(problem_, s.x);
  if (n.curve.status == LocalCurveStatus::kOk) {
    n.kind = classify(n.curve.h);
    // A point of a curve of tangential contact: a march along a transversal branch met it where
    // the branch crosses that curve, but the location converged to the nearest contact point;
    // move to the crossing (docs/math/tangential_contact.md §3).
    if (n.kind.type == SingularType::kTangentialContact) {
      if (auto c = crossing_near(problem_, n.location.x, 0.1 * problem_.scale())) {
        for (std::size_t i = 0; i < nodes_.size(); ++i)
          if ((nodes_[i].location.point - c->point).norm() <= merge_) return static_cast<int>(i);
        n.location = *c;
        n.location.x = problem_.wrap(c->x);
        n.curve = local_curve(problem_, n.location.x);
        n.kind = classify(n.curve.h);
      }
    }
    n.branches = half_branches(problem_, n.curve, n.kind);
  }
  n.used.assign(n.branches.size(), false);
  nodes_.push_back(std::move(n));
  return static_cast<int>(nodes_.size()) - 1;
}

int SingularRegistry::arriving_half_branch(int index, const CurvePoint& last) const {
  const SingularNode& n = nodes_[static_cast<std::size_t>(index)];
  const Vec3 d = last.p - n.location.point;
  int best = -1;
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n.branches.size(); ++i) {
    const HalfBranch& b = n.branches[i];
    const double X = d.dot(b.tangent_3d);
    if (!(X > 0) || b.line < 0) continue;
    // Offset from the tangent line along the line's normal rot90(direction) (half_branches.cpp).
    const Vec2& dir = n.kind.tangent_cone[static_cast<std::size_t>(b.line)].direction;
    const Vec3 normal = n.curve.direction_3d(Vec2(-dir[1], dir[0]));
    const double gamma = b.offset_exponent > 0 ? b.offset_exponent : 2.0;
    const Vec3 predicted = n.location.point + X * b.tangent_3d + b.offset_coefficient * std::pow(X, gamma) * normal;
    const double score = (last.p - predicted).norm();
    if (score < best_score) best_score = score, best = static_cast<int>(i);
  }
  return best;
}

void SingularRegistry::mark(int index, int half, int curve) {
  SingularNode& n = nodes_[static_cast<std::size_t>(index)];
  if (half >= 0) n.used[static_cast<std::size_t>(half)] = true;
  if (std::find(n.curves.begin(), n.curves.end(), curve) == n.curves.end()) {
    n.curves.push_back(curve);
    std::sort(n.curves.begin(), n.curves.end());
  }
}

SingularPointReport make_report(const SingularLocation& s, const Classification& kind,
                                const std::vector<HalfBranch>& branches) {
  SingularPointReport r;
  r.x = s.x;
  r.p = s.point;
  r.type = std::string(to_string(kind.type));
  r.ak = kind.ak;
  r.multiplicity = kind.multiplicity;
  r.milnor = kind.milnor;
  for (const HalfBranch& b : branches) {
    SingularPointReport::HalfBranch h{b.tangent_3d, b.param_tangent, b.leading_coefficient, b.leading_exponent, b.continuation, {}, b.normal_3d};
    for (const PuiseuxTerm& t : b.expansion.terms) h.expansion.push_back({t.exponent, t.coefficient});
    r.half_branches.push_back(std::move(h));
  }
  return r;
}

std::vector<SingularPointReport> SingularRegistry::reports() const {
  std::vector<SingularPointReport> out;
  for (const SingularNode& n : nodes_) {
    SingularPointReport r = make_report(n.location, n.kind, n.branches);
    r.curves = n.curves;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace ssimarch
