#include "ssimarch/start/patch_exclusion.hpp"
#include "ssimarch/start/interval_forms.hpp"

#include <cmath>

#include "ssimarch/problem/closed_form_tolerances.hpp"
#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/start/gradient.hpp"

namespace ssimarch {

namespace {

using G2 = Gradient<IntervalNumber, 2>;

// A parametric patch S(a x b) on intervals: S and its two partials over the patch, S at the
// patch's middle m, and a - m_a, b - m_b (the mean-value form's offsets).
struct Patch {
  Vec3T<G2> over;
  Vec3T<IntervalNumber> at_mid;
  IntervalNumber da, db;
};

Patch enclose(const Surface& s, const IntervalNumber& a, const IntervalNumber& b) {
  const IntervalNumber ma(a.mid()), mb(b.mid());
  return {s.point(G2(a, 0), G2(b, 1)), s.point(ma, mb), a - ma, b - mb};
}

// The natural enclosure `natural` intersected with the mean-value form value(m) + d . (X - m)
// (both enclose the range, so their intersection does).
IntervalNumber tighter(const IntervalNumber& natural, const IntervalNumber& mean_value) {
  bool empty = false;
  const IntervalNumber both = intersect(natural, mean_value, &empty);
  return empty ? natural : both;  // empty only by rounding beyond the outward steps
}

// An enclosure of f(S) over the patch, f the implicit form of `implicit`.
IntervalNumber implicit_on(const Patch& p, const Surface& implicit) {
  const G2 g = implicit.value(p.over);
  return tighter(g.v, implicit.value(p.at_mid) + g.d[0] * p.da + g.d[1] * p.db);
}

// An enclosure of the projection d . S over the patch.
IntervalNumber along(const Patch& p, const Vec3& d) {
  const IntervalNumber x(d.x()), y(d.y()), z(d.z());
  const G2 g = G2(d.x()) * p.over.x + G2(d.y()) * p.over.y + G2(d.z()) * p.over.z;
  return tighter(g.v, x * p.at_mid.x + y * p.at_mid.y + z * p.at_mid.z + g.d[0] * p.da + g.d[1] * p.db);
}

Vec3 middle(const Patch& p) { return {p.at_mid.x.mid(), p.at_mid.y.mid(), p.at_mid.z.mid()}; }
Vec3 normal(const Patch& p) {
  const Vec3 a(p.over.x.d[0].mid(), p.over.y.d[0].mid(), p.over.z.d[0].mid());
  const Vec3 b(p.over.x.d[1].mid(), p.over.y.d[1].mid(), p.over.z.d[1].mid());
  return a.cross(b);
}

bool misses(const IntervalNumber& f, double slack) { return f.lo() > slack || f.hi() < -slack; }

// Whether the projections of the two patches on d (any nonzero finite direction) are disjoint.
bool separated_along(const Patch& f, const Patch& g, const Vec3& d) {
  if (!(d.norm() > 0) || !d.allFinite()) return false;
  bool empty = false;
  intersect(along(f, d), along(g, d), &empty);
  return empty;
}

}  // namespace

bool patch_exclusion_applies(const Problem& P) {
  return P.kind() == PairKind::kParametricParametric && evaluates_on_intervals(P.first()) &&
         evaluates_on_intervals(P.second());
}

bool patches_cannot_meet(const Problem& P, const IntervalNumber* x) {
  const Patch f = enclose(P.first(), x[0], x[1]), g = enclose(P.second(), x[2], x[3]);
  const double slack = kImplicitFormSlack * P.scale();
  if (P.second().is_implicit() && misses(implicit_on(f, P.second()), slack)) return true;
  if (P.first().is_implicit() && misses(implicit_on(g, P.first()), slack)) return true;
  // Separating axes: the line between the patches' middles, and each patch's normal there.
  return separated_along(f, g, middle(f) - middle(g)) || separated_along(f, g, normal(f)) ||
         separated_along(f, g, normal(g));
}

bool singular_exclusion_applies(const Problem& P) {
  return (P.kind() == PairKind::kParametricImplicit || P.kind() == PairKind::kParametricParametric) &&
         P.second().is_implicit() && evaluates_on_intervals(P.first()) && evaluates_on_intervals(P.second());
}

bool patch_holds_no_singular_point(const Problem& P, const IntervalNumber& u, const IntervalNumber& v, int depth) {
  const Patch f = enclose(P.first(), u, v);
  const G2 g = P.second().value(f.over);
  // The gap's enclosure; the partials' slack is relative to their own size (for a
  // parametric-parametric pair, G's implicit normal is its parametric one to rounding).
  const IntervalNumber gap = tighter(g.v, P.second().value(f.at_mid) + g.d[0] * f.da + g.d[1] * f.db);
  if (misses(gap, kImplicitFormSlack * P.scale())) return true;
  for (const IntervalNumber& d : g.d)
    if (misses(d, kImplicitFormSlack * d.magnitude())) return true;
  if (depth <= 0) return false;
  const std::vector<Interval>& B = P.bounds();
  const bool split_u = u.width() / B[0].width() >= v.width() / B[1].width();
  const IntervalNumber& w = split_u ? u : v;
  const IntervalNumber lo(w.lo(), w.mid()), hi(w.mid(), w.hi());
  return split_u
             ? patch_holds_no_singular_point(P, lo, v, depth - 1) && patch_holds_no_singular_point(P, hi, v, depth - 1)
             : patch_holds_no_singular_point(P, u, lo, depth - 1) && patch_holds_no_singular_point(P, u, hi, depth - 1);
}

}  // namespace ssimarch
