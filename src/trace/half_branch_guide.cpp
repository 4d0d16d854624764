#include "ssimarch/trace/half_branch_guide.hpp"

#include <cmath>
#include <limits>

namespace ssimarch {

namespace {

struct Germ {
  Vec3 p0, t, n;
  PuiseuxExpansion w;
};

double offset(const PuiseuxExpansion& e, double X) {
  double w = 0;
  for (const PuiseuxTerm& term : e.terms) w += term.coefficient * std::pow(X, term.exponent);
  return w;
}

}  // namespace

CurveGuide half_branch_guide(const std::vector<SingularNode>& nodes) {
  std::vector<Germ> germs;
  for (const SingularNode& node : nodes)
    if (node.analysed())
      for (const HalfBranch& b : node.branches)
        if (b.tangent_3d.norm() > 0 && b.normal_3d.norm() > 0)
          germs.push_back({node.location.point, b.tangent_3d, b.normal_3d, b.expansion});
  if (germs.empty()) return {};
  return [germs = std::move(germs)](const Vec3& a, const Vec3& b) -> std::optional<Vec3> {
    const double c = (b - a).norm();
    const Germ* best = nullptr;
    double best_fit = kHalfBranchGuideFit * c, best_x = 0;
    for (const Germ& g : germs) {
      const double xa = (a - g.p0).dot(g.t), xb = (b - g.p0).dot(g.t);
      if (!(xa >= 0 && xb >= 0)) continue;  // W(X) is this half-branch's only for X >= 0
      const double fit =
          std::max(std::fabs(offset(g.w, xa) - (a - g.p0).dot(g.n)), std::fabs(offset(g.w, xb) - (b - g.p0).dot(g.n)));
      if (fit <= best_fit) best = &g, best_fit = fit, best_x = 0.5 * (xa + xb);
    }
    if (!best) return std::nullopt;
    // Off the tangent plane the expansion says nothing: a branch lying in the plane of its tangent
    // and the normal fits W = 0 at every distance, where the tangent line is far from the curve.
    const Vec3 g = best->p0 + best_x * best->t + offset(best->w, best_x) * best->n;
    if (!((g - 0.5 * (a + b)).norm() <= kHalfBranchGuideReach * c)) return std::nullopt;
    return g;
  };
}

}  // namespace ssimarch
