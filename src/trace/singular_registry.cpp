#include "ssimarch/trace/singular_registry.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "ssimarch/trace/tangential_contact.hpp"
#include "ssimarch/trace/trace_tolerances.hpp"

namespace ssimarch {

int SingularRegistry::add(const SingularLocation& s) {
  auto known = [&](const Vec3& p) -> std::optional<int> {
    for (std::size_t i = 0; i < nodes_.size(); ++i)
      if ((nodes_[i].location.point - p).norm() <= merge_) return static_cast<int>(i);
    return std::nullopt;
  };
  if (const std::optional<int> same = known(s.point)) return *same;
  SingularAnalysisOptions without_branches;
  without_branches.half_branches = false;
  SingularNode n;
  static_cast<SingularAnalysis&>(n) = analyse_singular_point(problem_, s, without_branches);
  n.location.x = problem_.wrap(s.x);
  // A point of a curve of tangential contact: a march along a transversal branch met it where
  // the branch crosses that curve, but the location converged to the nearest contact point;
  // move to the crossing (docs/math/tangential_contact.md §3).
  if (n.analysed() && n.kind.type == SingularType::kTangentialContact) {
    if (auto c = crossing_near(problem_, n.location.x, kCrossingSearchReach * problem_.scale())) {
      if (const std::optional<int> same = known(c->point)) return *same;
      SingularLocation at = *c;
      at.x = problem_.wrap(c->x);
      static_cast<SingularAnalysis&>(n) = analyse_singular_point(problem_, at, without_branches);
    }
  }
  // A node whose quadratic form is no larger than the location's error: the crossing it stands for.
  if (std::optional<SingularAnalysis> a = crossing_behind_node(problem_, n, merge_, without_branches)) {
    if (const std::optional<int> same = known(a->location.point)) return *same;
    a->location.x = problem_.wrap(a->location.x);
    static_cast<SingularAnalysis&>(n) = std::move(*a);
  }
  if (const std::optional<int> same = within_resolution(n)) return *same;
  with_half_branches(problem_, &n);
  n.used.assign(n.branches.size(), false);
  nodes_.push_back(std::move(n));
  return static_cast<int>(nodes_.size()) - 1;
}

std::optional<int> SingularRegistry::within_resolution(const SingularNode& n) {
  for (std::size_t i = 0; i < nodes_.size(); ++i) {
    SingularNode& e = nodes_[i];
    const double d = (e.location.point - n.location.point).norm();
    if (d > std::max(resolution_radius(e), resolution_radius(n))) continue;
    // The more degenerate of the two is the point itself, the other a location that stopped short
    // of it; a node whose half-branches a curve has used keeps them.
    const bool unused = std::none_of(e.used.begin(), e.used.end(), [](bool u) { return u; });
    if (n.kind.milnor > e.kind.milnor && unused) {
      static_cast<SingularAnalysis&>(e) = n;
      with_half_branches(problem_, &e);
      e.used.assign(e.branches.size(), false);
    }
    return static_cast<int>(i);
  }
  return std::nullopt;
}

namespace {

// The point of half-branch b of node n at the distance X along its tangent: from its expansion over
// the tangent plane where it has one (every term to exponent 6: the two halves of a ramphoid cusp
// share their leading term X^2 and part at X^(5/2)), else from the leading offset c X^gamma along
// the normal of its tangent-cone line (half_branches.cpp).
Vec3 predicted_point(const SingularNode& n, const HalfBranch& b, double X) {
  if (!b.expansion.terms.empty()) {
    double w = 0;
    for (const PuiseuxTerm& t : b.expansion.terms) w += t.coefficient * std::pow(X, t.exponent);
    return n.location.point + X * b.tangent_3d + w * b.normal_3d;
  }
  const Vec2& dir = n.kind.tangent_cone[static_cast<std::size_t>(b.line)].direction;
  const Vec3 normal = n.curve.direction_3d(Vec2(-dir[1], dir[0]));
  const double gamma = b.offset_exponent > 0 ? b.offset_exponent : 2.0;
  return n.location.point + X * b.tangent_3d + b.offset_coefficient * std::pow(X, gamma) * normal;
}

}  // namespace

int SingularRegistry::arriving_half_branch(int index, const CurvePoint& last) const {
  const SingularNode& n = nodes_[static_cast<std::size_t>(index)];
  const Vec3 d = last.p - n.location.point;
  int best = -1;
  double best_score = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < n.branches.size(); ++i) {
    const HalfBranch& b = n.branches[i];
    const double X = d.dot(b.tangent_3d);
    if (!(X > 0) || b.line < 0) continue;
    const double score = (last.p - predicted_point(n, b, X)).norm();
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

SingularPointReport make_report(const SingularAnalysis& a, bool with_branches) {
  SingularPointReport r;
  r.x = a.location.x;
  r.p = a.location.point;
  r.type = a.kind.type;
  r.ak = a.kind.ak;
  r.multiplicity = a.kind.multiplicity;
  r.milnor = a.kind.milnor;
  for (const HalfBranch& b : with_branches ? a.branches : std::vector<HalfBranch>{}) {
    SingularPointReport::HalfBranch h{
        b.tangent_3d, b.param_tangent, b.leading_coefficient, b.leading_exponent, b.continuation, {}, b.normal_3d};
    for (const PuiseuxTerm& t : b.expansion.terms) h.expansion.push_back({t.exponent, t.coefficient});
    r.half_branches.push_back(std::move(h));
  }
  return r;
}

std::vector<SingularPointReport> SingularRegistry::reports() const {
  std::vector<SingularPointReport> out;
  for (const SingularNode& n : nodes_) {
    SingularPointReport r = make_report(n);
    r.curves = n.curves;
    out.push_back(std::move(r));
  }
  return out;
}

}  // namespace ssimarch
