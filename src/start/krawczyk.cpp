#include "ssimarch/start/krawczyk.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <deque>
#include <limits>

#include "ssimarch/core/interrupt.hpp"

namespace ssimarch {

namespace {

constexpr double kInflation = 0.02;   // boxes are tested inflated by this fraction per side
constexpr double kContraction = 0.7;  // K ∩ X at most this wide (relative) is kept and tested again
constexpr double kMinReciprocalCondition = 1e-14;
constexpr int kMaxRefinements = 60;
constexpr bool kSmearSplit = true;

bool excluded_by_value(const SquareSystem& s, const IntervalBox& x) {
  IntervalNumber g[kMaxSystemDimension];
  s.value(x.data(), g);
  for (int i = 0; i < s.dimension; ++i)
    if (!g[i].contains_zero()) return true;
  return false;
}

double max_relative_width(const IntervalBox& x, const std::vector<double>& scale);

// Every side pushed out by kInflation times the box's largest relative width (so a side that
// contraction made very thin, e.g. against a face of the start box, still gets room), and by a
// floor above the rounding errors of evaluating g.
IntervalBox inflate(const IntervalBox& x, const std::vector<double>& scale) {
  IntervalBox r(x.size());
  const double rel = max_relative_width(x, scale);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double w = kInflation * rel * scale[i] + 1e-14 * std::max(x[i].magnitude(), scale[i]);
    r[i] = IntervalNumber(x[i].lo() - w, x[i].hi() + w);
  }
  return r;
}

double max_relative_width(const IntervalBox& x, const std::vector<double>& scale) {
  double w = 0;
  for (std::size_t i = 0; i < x.size(); ++i) w = std::max(w, x[i].width() / scale[i]);
  return w;
}

bool interior(const IntervalBox& k, const IntervalBox& x) {
  for (std::size_t i = 0; i < x.size(); ++i)
    if (!k[i].interior_of(x[i])) return false;
  return true;
}

// K ∩ X; false when empty.
bool intersect_box(const IntervalBox& k, IntervalBox* x) {
  for (std::size_t i = 0; i < x->size(); ++i) {
    bool empty = false;
    (*x)[i] = intersect(k[i], (*x)[i], &empty);
    if (empty) return false;
  }
  return true;
}

// Krawczyk iterations from a box with a proven unique root down to an enclosure of root_width.
IntervalBox refine(const SquareSystem& s, IntervalBox x, double root_width) {
  for (int it = 0; it < kMaxRefinements; ++it) {
    bool small = true;
    for (const IntervalNumber& c : x)
      if (c.width() > root_width * std::max(1.0, c.magnitude())) small = false;
    if (small) break;
    bool ok = false;
    IntervalBox k = krawczyk(s, x, &ok);
    if (!ok) break;
    IntervalBox next = x;
    if (!intersect_box(k, &next)) break;  // cannot happen with a root inside; keep the last box
    bool shrank = false;
    for (std::size_t i = 0; i < x.size(); ++i)
      if (next[i].width() < x[i].width()) shrank = true;
    x = next;
    if (!shrank) break;
  }
  return x;
}

// Splits x across the coordinate of largest smear max_i |dg_i/dx_k| w(X_k) (Kearfott,
// "Rigorous Global Search: Continuous Problems", 1996, §5.2; Csendes & Ratz, "Subdivision
// direction selection in interval methods for global optimization", SIAM J. Numer. Anal. 34,
// 1997): the coordinate along which g varies most over the box, whose halving shrinks the
// enclosures most, so boxes come out long where g is flat. `slope[k]` = max_i |dg_i/dx_k| over
// the box (none: the widest coordinate relative to the start box). A coordinate whose relative
// width is kSmearWidthGuard times the chosen one's is split instead, so every width goes to 0.
constexpr double kSmearWidthGuard = 1e3;
std::pair<IntervalBox, IntervalBox> bisect(const IntervalBox& x, const std::vector<double>& scale,
                                           const double* slope) {
  std::size_t widest = 0, k = 0;
  for (std::size_t i = 1; i < x.size(); ++i)
    if (x[i].width() / scale[i] > x[widest].width() / scale[widest]) widest = i;
  k = widest;
  if (slope) {
    double best = -1;
    for (std::size_t i = 0; i < x.size(); ++i) {
      const double smear = slope[i] * x[i].width();
      if (!std::isfinite(smear)) {
        best = -1;
        break;
      }
      if (smear > best) best = smear, k = i;
    }
    if (!(best > 0) || x[widest].width() / scale[widest] > kSmearWidthGuard * x[k].width() / scale[k]) k = widest;
  }
  const double m = x[k].mid();
  IntervalBox a = x, b = x;
  a[k] = IntervalNumber(x[k].lo(), m);
  b[k] = IntervalNumber(m, x[k].hi());
  return {a, b};
}

bool inside(const IntervalBox& a, const IntervalBox& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].lo() < b[i].lo() || a[i].hi() > b[i].hi()) return false;
  return true;
}

bool meets(const IntervalBox& a, const IntervalBox& b) {
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].hi() < b[i].lo() || b[i].hi() < a[i].lo()) return false;
  return true;
}

void add_root(const SquareSystem& s, const IntervalBox& unique_in, const IntervalBox& start, double root_width,
              std::vector<CertifiedRoot>* roots) {
  IntervalBox e = refine(s, unique_in, root_width);
  if (!meets(e, start)) return;          // the inflated box's root lies outside the start box
  for (const CertifiedRoot& r : *roots)  // the same root, proven unique in an overlapping box
    if (inside(e, r.unique_in) || inside(r.enclosure, unique_in)) return;
  CertifiedRoot r{e, unique_in, VecX(static_cast<Eigen::Index>(e.size()))};
  for (std::size_t i = 0; i < e.size(); ++i) r.x[static_cast<Eigen::Index>(i)] = e[i].mid();
  roots->push_back(std::move(r));
}

}  // namespace

namespace {

// One gradient evaluation on xe serves two tests of the box x ⊆ xe (both with m = mid xe):
//  - the mean-value form g(x) ⊆ g(m) + J(xe)(x - m) (Moore, Kearfott & Cloud 2009, §6.4): a
//    first-order enclosure whose overestimation shrinks with the box times |J|, where the natural
//    extension's does not shrink below the dependency effect; near a singular root, where J
//    itself is small, it excludes boxes far closer to the root (fewer boxes in the cluster);
//  - the Krawczyk operator K(xe) (see the header), when J(m) can be inverted.
struct Step {
  IntervalBox k;
  bool ok = false;                         // K formed
  bool excluded = false;                   // the mean-value form of some g_i on x misses 0
  double slope[kMaxSystemDimension] = {};  // max_i |dg_i/dx_j| over xe (bisect's smear)
};

// g's interval Jacobian on xe into jac[i][j] (= dg_i/dx_j), by the gradient with N slots.
template <int N, class G>
void jacobian_on(const G& gradient, int n, const IntervalBox& xe, IntervalNumber (*jac)[kMaxSystemDimension]) {
  Gradient<IntervalNumber, N> xv[kMaxSystemDimension], gv[kMaxSystemDimension];
  for (int i = 0; i < n; ++i) xv[i] = Gradient<IntervalNumber, N>(xe[static_cast<std::size_t>(i)], i);
  gradient(xv, gv);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) jac[i][j] = gv[i].d[static_cast<std::size_t>(j)];
}

Step krawczyk_step(const SquareSystem& s, const IntervalBox& xe, const IntervalBox* x) {
  const int n = s.dimension;
  Step out;
  IntervalNumber jac[kMaxSystemDimension][kMaxSystemDimension];
  if (n == 2 && s.gradient2)
    jacobian_on<2>(s.gradient2, n, xe, jac);
  else if (n == 3 && s.gradient3)
    jacobian_on<3>(s.gradient3, n, xe, jac);
  else
    jacobian_on<kMaxSystemDimension>(s.gradient, n, xe, jac);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double mag = jac[i][j].magnitude();
      out.slope[j] = std::isnan(mag) ? std::numeric_limits<double>::infinity() : std::max(out.slope[j], mag);
    }
  IntervalNumber m[kMaxSystemDimension], gm[kMaxSystemDimension];
  for (int i = 0; i < n; ++i) m[i] = IntervalNumber(xe[static_cast<std::size_t>(i)].mid());
  s.value(m, gm);
  if (x)
    for (int i = 0; i < n && !out.excluded; ++i) {
      IntervalNumber gi = gm[i];
      for (int j = 0; j < n; ++j) gi = gi + jac[i][j] * ((*x)[static_cast<std::size_t>(j)] - m[j]);
      out.excluded = !gi.contains_zero();
    }
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, 0, kMaxSystemDimension, kMaxSystemDimension> jm(n, n);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) jm(i, j) = jac[i][j].mid();
  if (!jm.allFinite()) return out;
  Eigen::FullPivLU<decltype(jm)> lu(jm);
  out.ok = lu.isInvertible() && lu.rcond() > kMinReciprocalCondition;
  if (!out.ok) return out;
  const decltype(jm) y = lu.inverse();
  out.k.resize(xe.size());
  for (int i = 0; i < n; ++i) {
    IntervalNumber ki = m[i];
    for (int j = 0; j < n; ++j) ki = ki - y(i, j) * gm[j];
    for (int j = 0; j < n; ++j) {
      IntervalNumber c = IntervalNumber(i == j ? 1.0 : 0.0);  // (I - Y J(X))_ij
      for (int l = 0; l < n; ++l) c = c - y(i, l) * jac[l][j];
      ki = ki + c * (xe[static_cast<std::size_t>(j)] - m[j]);
    }
    out.k[static_cast<std::size_t>(i)] = ki;
  }
  return out;
}

}  // namespace

IntervalBox krawczyk(const SquareSystem& s, const IntervalBox& x, bool* ok) {
  Step st = krawczyk_step(s, x, nullptr);
  *ok = st.ok;
  return st.ok ? std::move(st.k) : x;
}

RootSearchResult find_all_roots(const SquareSystem& s, const IntervalBox& start, const RootSearchOptions& o) {
  RootSearchResult out;
  std::vector<double> scale(start.size());
  for (std::size_t i = 0; i < start.size(); ++i) scale[i] = std::max(start[i].width(), 1e-300);
  std::deque<IntervalBox> queue{start};
  while (!queue.empty()) {
    if (out.boxes >= o.max_boxes) {
      for (IntervalBox& b : queue) out.undecided.push_back({std::move(b), true});
      break;
    }
    throw_if_interrupted();  // Ctrl-C (core/interrupt.hpp)
    IntervalBox x = std::move(queue.front());
    queue.pop_front();
    ++out.boxes;
    if ((s.excluded && s.excluded(x)) || excluded_by_value(s, x)) continue;
    const IntervalBox xe = inflate(x, scale);
    Step st = krawczyk_step(s, xe, &x);
    if (st.excluded) continue;
    const bool ok = st.ok;
    const IntervalBox& k = st.k;
    if (ok && interior(k, xe)) {
      add_root(s, xe, start, o.root_width, &out.roots);
      continue;
    }
    if (ok && !intersect_box(k, &x)) continue;  // K(Xe) ∩ X = ∅: no root in X
    if (max_relative_width(x, scale) < o.min_width) {
      out.undecided.push_back({x, false});
      continue;
    }
    if (ok && max_relative_width(x, scale) < kContraction * max_relative_width(xe, scale)) {
      queue.push_back(std::move(x));  // contracted well: test the smaller box again
      continue;
    }
    auto [a, b] = bisect(x, scale, kSmearSplit ? st.slope : nullptr);
    queue.push_back(std::move(a));
    queue.push_back(std::move(b));
  }
  return out;
}

}  // namespace ssimarch
