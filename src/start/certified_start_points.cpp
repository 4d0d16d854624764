#include "ssimarch/start/certified_start_points.hpp"
#include "ssimarch/start/interval_forms.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <optional>

#include "ssimarch/core/progress.hpp"
#include "ssimarch/core/thread_pool.hpp"

#include "ssimarch/problem/closed_form_tolerances.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/poles_and_trims.hpp"
#include "ssimarch/problem/singular_tolerances.hpp"
#include "ssimarch/singular/locate.hpp"
#include "ssimarch/start/isolated_box.hpp"
#include "ssimarch/start/patch_exclusion.hpp"
#include "ssimarch/start/krawczyk.hpp"
#include "ssimarch/start/start_tolerances.hpp"
#include "ssimarch/start/saddle_box.hpp"
#include "ssimarch/start/start_points.hpp"

namespace ssimarch {

namespace {

// H with x_fixed = at, as a function of the other unknowns y.
template <class T>
void boundary_residual(const Problem& P, int fixed, double at, const T* y, T* g) {
  T x[kMaxSystemDimension];
  for (int i = 0, j = 0; i < P.dim(); ++i) x[i] = i == fixed ? T(at) : y[j++];
  P.residual(x, g);
}

template <class T>
T determinant(const T (&m)[3][3], int size) {
  if (size == 1) return m[0][0];
  if (size == 2) return m[0][0] * m[1][1] - m[0][1] * m[1][0];
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) - m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

// (H(x), det of J_H without column k): the tangent's x_k component vanishes (see the header).
// N = n derivatives exactly: the nested interval gradients' cost grows with N squared, and
// kMaxSystemDimension where n = 2 did three times the work (docs/benchmarks.md, profiles).
template <int N, class T>
void turning_residual_n(const Problem& P, int k, const T* x, T* g) {
  using D = Gradient<T, N>;
  const int n = N;
  D xd[kMaxSystemDimension], h[kMaxSystemDimension - 1];
  for (int i = 0; i < n; ++i) xd[i] = D(x[i], i);
  P.residual(xd, h);
  T minor[3][3];
  for (int r = 0; r < n - 1; ++r) {
    g[r] = h[r].v;
    for (int c = 0, j = 0; c < n; ++c)
      if (c != k) minor[r][j++] = h[r].d[static_cast<std::size_t>(c)];
  }
  g[n - 1] = determinant(minor, n - 1);
}

template <class T>
void turning_residual(const Problem& P, int k, const T* x, T* g) {
  switch (P.dim()) {
    case 2: return turning_residual_n<2>(P, k, x, g);
    case 3: return turning_residual_n<3>(P, k, x, g);
    default: return turning_residual_n<4>(P, k, x, g);
  }
}

// For a parametric-parametric pair, the patch exclusion (start/patch_exclusion.hpp)
// of a system whose unknowns are H's with x_fixed = at removed (fixed < 0: all of H's).
void add_patch_exclusion(const Problem& P, int fixed, double at, SquareSystem* e) {
  if (!patch_exclusion_applies(P)) return;
  e->excluded = [&P, fixed, at](const IntervalBox& y) {
    IntervalNumber x[kMaxSystemDimension];
    for (int i = 0, j = 0; i < P.dim(); ++i) x[i] = i == fixed ? IntervalNumber(at) : y[static_cast<std::size_t>(j++)];
    return patches_cannot_meet(P, x);
  };
}

}  // namespace

SquareSystem face_system(const Problem& P, int i, double at) {
  SquareSystem e;
  e.dimension = P.dim() - 1;
  add_patch_exclusion(P, i, at, &e);
  e.value = [&P, i, at](const IntervalNumber* y, IntervalNumber* g) { boundary_residual(P, i, at, y, g); };
  set_gradients(&e, [&P, i, at](const auto* y, auto* g) { boundary_residual(P, i, at, y, g); });
  return e;
}

namespace {

struct System {
  SquareSystem equations;
  IntervalBox box;
  std::string name;
  int fixed = -1;  // the unknown held at `at` (boundary systems)
  double at = 0;
};

std::vector<System> boundary_systems(const Problem& P) {
  std::vector<System> out;
  const auto names = P.unknown_names();
  for (int i = 0; i < P.dim(); ++i) {
    const Interval& b = P.bounds()[static_cast<std::size_t>(i)];
    std::vector<double> ends{b.lo};
    if (P.periods()[static_cast<std::size_t>(i)] == 0.0) ends.push_back(b.hi);
    for (double at : ends) {
      System s;
      s.fixed = i;
      s.at = at;
      char value[32];
      std::snprintf(value, sizeof value, "%.9g", at);
      s.name = "boundary " + names[static_cast<std::size_t>(i)] + " = " + value;
      s.equations = face_system(P, i, at);
      for (int j = 0; j < P.dim(); ++j)
        if (j != i)
          s.box.emplace_back(P.bounds()[static_cast<std::size_t>(j)].lo, P.bounds()[static_cast<std::size_t>(j)].hi);
      out.push_back(std::move(s));
    }
  }
  return out;
}

// The trim faces' systems (issue 11 item 5: every surface's trim is honoured): H(x) = 0 and
// n . point(x) = b for each face n . p = b of a trim of a surface in implicit form
// (surface/trims.hpp): n equations in the n unknowns over the whole box. A branch whose piece
// inside the trims leaves through a trim face meets it in an isolated root, as a branch leaving
// the box meets a box face; without them the start points of such a piece were only the box
// faces' and turning points' roots beyond the trim, moved onto it by Newton (onto_trims).
template <class T>
void trim_face_residual(const Problem& P, const Vec3& normal, double at, const T* x, T* g) {
  P.residual(x, g);
  const Vec3T<T> p = P.point(x);
  g[P.dim() - 1] = T(normal.x()) * p.x + T(normal.y()) * p.y + T(normal.z()) * p.z - T(at);
}

std::vector<System> trim_face_systems(const Problem& P) {
  std::vector<System> out;
  for (const Slab& slab : problem_trims(P))
    for (double at : {slab.range.lo, slab.range.hi}) {
      System s;
      const Vec3 n = slab.normal;
      char name[96];
      std::snprintf(name, sizeof name, "trim face (%.6g, %.6g, %.6g) . p = %.9g", n.x(), n.y(), n.z(), at);
      s.name = name;
      s.equations.dimension = P.dim();
      s.equations.value = [&P, n, at](const IntervalNumber* x, IntervalNumber* g) {
        trim_face_residual(P, n, at, x, g);
      };
      set_gradients(&s.equations, [&P, n, at](const auto* x, auto* g) { trim_face_residual(P, n, at, x, g); });
      add_patch_exclusion(P, -1, 0.0, &s.equations);
      for (const Interval& b : P.bounds()) s.box.emplace_back(b.lo, b.hi);
      out.push_back(std::move(s));
    }
  return out;
}

System turning_system(const Problem& P, int k) {
  System s;
  s.name = "turning d" + P.unknown_names()[static_cast<std::size_t>(k)] + " = 0";
  s.equations.dimension = P.dim();
  s.equations.value = [&P, k](const IntervalNumber* x, IntervalNumber* g) { turning_residual(P, k, x, g); };
  set_gradients(&s.equations, [&P, k](const auto* x, auto* g) { turning_residual(P, k, x, g); });
  add_patch_exclusion(P, -1, 0.0, &s.equations);
  for (const Interval& b : P.bounds()) s.box.emplace_back(b.lo, b.hi);
  return s;
}

// The unknowns x of H from a point or box of a system's unknowns.
IntervalBox to_unknowns(const System& s, const IntervalBox& y) {
  if (s.fixed < 0) return y;
  IntervalBox x;
  for (std::size_t i = 0, j = 0; i <= y.size(); ++i)
    x.push_back(static_cast<int>(i) == s.fixed ? IntervalNumber(s.at) : y[j++]);
  return x;
}

// A boundary face x_fixed = at of a parametric-implicit pair that the parametric surface maps
// into one point to within `tolerance` (a pole: a sphere's or a cone's collapsed row). Its system
// is H of that point over the whole face: no root, or the whole face (a continuum the search
// cannot decide: it spent its budget there, issue 27). Every branch that meets the face passes
// within the tolerance of the face's middle, so a candidate start point there decides the system.
// The interval enclosure of the surface over the face, not a sampled test, says it is one point.
std::optional<VecX> collapsed_face(const Problem& P, const System& s, double tolerance) {
  if (P.kind() != PairKind::kParametricImplicit || s.fixed < 0) return std::nullopt;
  const IntervalBox x = to_unknowns(s, s.box);
  const Vec3T<IntervalNumber> p = P.point(x.data());
  if (!(std::max({p.x.width(), p.y.width(), p.z.width()}) <= tolerance)) return std::nullopt;
  VecX mid(static_cast<Eigen::Index>(x.size()));
  for (std::size_t i = 0; i < x.size(); ++i) mid[static_cast<Eigen::Index>(i)] = x[i].mid();
  return mid;
}

// Undecided boxes that touch merged into their hulls (a singular root leaves a cluster of them).
std::vector<IntervalBox> merge_touching(const std::vector<UndecidedBox>& boxes, bool budget) {
  std::vector<IntervalBox> regions;
  for (const UndecidedBox& u : boxes) {
    if (u.budget != budget) continue;
    IntervalBox b = u.box;
    for (bool merged = true; merged;) {
      merged = false;
      for (std::size_t r = 0; r < regions.size(); ++r) {
        bool touch = true;
        for (std::size_t i = 0; i < b.size(); ++i)
          if (b[i].hi() < regions[r][i].lo() || regions[r][i].hi() < b[i].lo()) touch = false;
        if (!touch) continue;
        for (std::size_t i = 0; i < b.size(); ++i) b[i] = hull(b[i], regions[r][i]);
        regions.erase(regions.begin() + static_cast<std::ptrdiff_t>(r));
        merged = true;
        break;
      }
    }
    regions.push_back(std::move(b));
  }
  return regions;
}

// A box decided around an isolated point (start/isolated_box.hpp): every point of the curve
// in `box` lies within `radius` (model units) of point(x).
struct IsolatedBox {
  IntervalBox box;  // a periodic unknown may reach past its period
  VecX x;
  double radius = 0;
};

struct Collector {
  const Tracer& tracer;
  TraceStats* stats;
  StartPointSearch* search;
  std::vector<VecX> points;
  std::vector<Vec3> at;  // P.point of each of `points`: the duplicate test below compares with
                         // all of them, thousands after the sampling of uncertain regions
  std::vector<IsolatedBox> isolated{};

  // x clamped into the bounds and polished by Newton when that keeps it close.
  void add(UnknownVec x, bool candidate) {
    const Problem& P = tracer.problem();
    clamp(&x);
    CorrectorResult r = gauss_newton(P, x, CorrectorOptions{tracer.options().tolerance, 20});
    stats->linearizations += r.linearizations;
    stats->add_surface_evaluations(r.evaluations);
    clamp(&r.x);
    const bool converged = r.status == CorrectorStatus::kConverged && P.linearize(r.x).distance <= 1e-9 * P.scale();
    if (converged && (candidate || (P.point(r.x) - P.point(x)).norm() < 1e-6 * P.scale()))
      x = r.x;
    else if (candidate)
      return;  // Newton from an undecided box found no point of the curve
    const Vec3 p = P.point(x);
    for (const Vec3& q : at)
      if ((q - p).norm() < 1e-9 * P.scale()) return;
    points.push_back(x);
    at.push_back(p);
  }

  // Into the bounds (a root on a face may come out a rounding error beyond it).
  void clamp(UnknownVec* x) const {
    const Problem& P = tracer.problem();
    for (int i = 0; i < P.dim(); ++i) {
      const Interval& b = P.bounds()[static_cast<std::size_t>(i)];
      if (P.periods()[static_cast<std::size_t>(i)] == 0.0) (*x)[i] = std::clamp((*x)[i], b.lo, b.hi);
    }
  }

  // Roots as start points, undecided boxes as candidates. Returns whether the system was decided
  // everywhere.
  bool take(const System& s, const RootSearchResult& r) {
    search->boxes += r.boxes;
    for (const CertifiedRoot& root : r.roots) {
      IntervalBox x = to_unknowns(s, root.enclosure);
      VecX v(static_cast<Eigen::Index>(x.size()));
      for (std::size_t i = 0; i < x.size(); ++i) v[static_cast<Eigen::Index>(i)] = x[i].mid();
      add(v, false);
    }
    for (bool budget : {false, true})
      for (const IntervalBox& y : merge_touching(r.undecided, budget)) {
        IntervalBox x = to_unknowns(s, y);
        VecX v(static_cast<Eigen::Index>(x.size()));
        for (std::size_t i = 0; i < x.size(); ++i) v[static_cast<Eigen::Index>(i)] = x[i].mid();
        if (!budget) add(v, true);
      }
    return r.complete();
  }

  // The undecided boxes of s as uncertain regions, but those inside an isolated box.
  void report(const System& s, const RootSearchResult& r) {
    for (bool budget : {false, true})
      for (const IntervalBox& y : merge_touching(r.undecided, budget)) {
        const IntervalBox x = to_unknowns(s, y);
        if (covered(x)) continue;
        UncertainRegion u{{}, s.name, budget ? UncertainReason::kBudgetSpent : UncertainReason::kSingularOrNonIsolated};
        for (const IntervalNumber& c : x) u.box.push_back({c.lo(), c.hi()});
        search->uncertain_regions.push_back(std::move(u));
      }
  }

  // Interval i of a region moved by whole periods (periodic unknowns) to lie nearest to `to`.
  IntervalNumber nearest_copy(int i, const IntervalNumber& c, double to) const {
    const double period = tracer.problem().periods()[static_cast<std::size_t>(i)];
    const double shift = period > 0 ? period * std::round((to - c.mid()) / period) : 0.0;
    return {c.lo() + shift, c.hi() + shift};
  }

  // Whether the region lies in a decided isolated box (modulo the periods).
  bool covered(const IntervalBox& region) const {
    for (const IsolatedBox& b : isolated) {
      bool inside = true;
      for (std::size_t i = 0; i < region.size() && inside; ++i) {
        const IntervalNumber c = nearest_copy(static_cast<int>(i), region[i], b.x[static_cast<Eigen::Index>(i)]);
        inside = b.box[i].lo() <= c.lo() && c.hi() <= b.box[i].hi();
      }
      if (inside) return true;
    }
    return false;
  }

  // The region decided as part of a box around an isolated point (start/isolated_box.hpp):
  // the singular point is located from the region's middle and boxes around it holding the
  // region, `factor` times its extent from the point plus kSaddleFloor of the domain, are tried.
  bool decide_isolated(const IntervalBox& region);
};

// The box S of a singular cluster tried as a saddle or isolated box: half-widths `factor` times
// the region's extent plus a floor of kSaddleFloor of the domain.
constexpr double kSaddleFloor = 1e-6;
constexpr double kClusterGrowth[] = {2.0, 5.0, 20.0};  // the sizes tried, as multiples of the region

bool Collector::decide_isolated(const IntervalBox& region) {
  if (covered(region)) return true;
  const Problem& P = tracer.problem();
  VecX guess(P.dim());
  for (int i = 0; i < P.dim(); ++i) guess[i] = region[static_cast<std::size_t>(i)].mid();
  const SingularLocation s = locate_singular_point(P, guess);
  if (s.status != LocateStatus::kConverged) return false;
  UnknownVec x0 = s.x;
  clamp(&x0);
  // The curve in the box within the resolution radius of the point is what the tracer reports as
  // the isolated point (trace_all.cpp, absorb_contact_loops); kIsolatedBoxRadius bounds it below.
  const double max_radius = std::min(kIsolatedBoxRadius * P.scale(), kResolutionFraction * tracer.spacing());
  // A gap within the corrector's tolerance is a contact, as the closed forms and the tracer have
  // it (tests NearContact.*): a deeper overlap is a loop to trace, not an isolated point.
  const double max_depth = contact_gap_tolerance(tracer.options().tolerance, P.scale());
  for (double factor : kClusterGrowth) {
    IntervalBox S;
    for (int i = 0; i < P.dim(); ++i) {
      const auto ui = static_cast<std::size_t>(i);
      const IntervalNumber c = nearest_copy(i, region[ui], x0[i]);
      const Interval& b = P.bounds()[ui];
      const double w =
          factor * std::max(std::abs(c.lo() - x0[i]), std::abs(c.hi() - x0[i])) + kSaddleFloor * (b.hi - b.lo);
      if (P.periods()[ui] > 0)
        S.emplace_back(x0[i] - w, x0[i] + w);
      else
        S.emplace_back(std::max(b.lo, x0[i] - w), std::min(b.hi, x0[i] + w));
    }
    ++search->boxes;
    const IsolatedBoxResult d = decide_isolated_box(P, x0, S, max_radius, max_depth);
    if (!d.decided) continue;
    isolated.push_back({S, x0, d.radius});
    // The point itself is a start: trace_all reports a start on an isolated point as that point
    // (after a certified search the tangency hunt looks nowhere).
    add(x0, false);
    return true;
  }
  return false;
}

// The box S of a singular cluster tried as a saddle box (start/saddle_box.hpp): the region
// grown by `factor` times its half-widths plus a floor of kSaddleFloor of the domain, clipped to
// the bounds.
constexpr long kSaddleFaceBoxes = 100;  // least box budget of each face system of a saddle box
// The turning systems' first pass gets the box budget divided by this (dimensionless).
constexpr long kTurningFirstPassDivisor = 4;
IntervalBox grown(const Problem& P, const IntervalBox& region, double factor) {
  IntervalBox out;
  for (std::size_t i = 0; i < region.size(); ++i) {
    const Interval& b = P.bounds()[i];
    const double w = factor * 0.5 * region[i].width() + kSaddleFloor * (b.hi - b.lo);
    out.emplace_back(std::max(b.lo, region[i].mid() - w), std::min(b.hi, region[i].mid() + w));
  }
  return out;
}

// The region of a turning system decided as a saddle box (no closed branch inside, every arc
// through it crossing its certified faces, whose roots become start points); tries a few sizes.
bool decide_saddle(const IntervalBox& region, const RootSearchOptions& ro, Collector* out, long* saddle_boxes) {
  const Problem& P = out->tracer.problem();
  if (P.dim() > 3) return false;  // saddle boxes need a reduction to two variables (saddle_box.hpp)
  // The faces of a small box need few boxes; a tenth of the budget bounds what a box that fails
  // (a face through a tangency) can cost, tried at three sizes per region.
  RootSearchOptions faces = ro;
  faces.max_boxes = std::max(kSaddleFaceBoxes, ro.max_boxes / 10);
  for (double factor : kClusterGrowth) {
    SaddleBoxResult b = decide_saddle_box(P, grown(P, region, factor), faces);
    out->search->boxes += b.boxes;
    if (!b.decided) continue;
    for (const VecX& x : b.crossings) out->add(x, false);
    ++*saddle_boxes;
    return true;
  }
  return false;
}

// Every undecided region of a system decided: inside a decided isolated box, as a saddle box
// (turning systems: `saddles`), or as a new isolated box. Returns whether all were.
bool decide_clusters(const System& s, const RootSearchResult& r, const RootSearchOptions& ro, bool saddles,
                     Collector* out, long* saddle_boxes) {
  for (bool budget : {false, true})
    for (const IntervalBox& y : merge_touching(r.undecided, budget)) {
      const IntervalBox region = to_unknowns(s, y);
      if (out->covered(region)) continue;
      if (saddles && decide_saddle(region, ro, out, saddle_boxes)) continue;
      if (!out->decide_isolated(region)) return false;
    }
  return true;
}

RootSearchResult in_unknowns(const System& s, RootSearchResult r) {
  for (CertifiedRoot& root : r.roots) {
    root.enclosure = to_unknowns(s, root.enclosure);
    root.unique_in = to_unknowns(s, root.unique_in);
    root.x = VecX(static_cast<Eigen::Index>(root.enclosure.size()));
    for (std::size_t i = 0; i < root.enclosure.size(); ++i)
      root.x[static_cast<Eigen::Index>(i)] = root.enclosure[i].mid();
  }
  for (UndecidedBox& u : r.undecided) u.box = to_unknowns(s, u.box);
  return r;
}

// Samples spent on the uncertain regions together (Newton from each), spread evenly over them.
constexpr double kRegionSampleBudget = 4096;

// When the search is not certified, start points the certificate cannot vouch for: Newton from
// samples inside every uncertain region (an undecided box may hold a whole closed branch whose
// turning points the budget did not reach), then from the sampling grid of the whole domain (the
// fallback of find_start_points). The result stays `certified: false`; trace_all skips the
// starts that lie on curves traced already, so a branch found twice is traced once.
void add_sampled_starts(Collector* out) {
  const Tracer& tracer = out->tracer;
  const Problem& P = tracer.problem();
  const std::vector<UncertainRegion>& regions = out->search->uncertain_regions;
  // Newton runs per region grow as samples^2 (parametric pairs pair F's samples with G's nearest)
  // or samples^3 (implicit-implicit).
  const double power = P.kind() == PairKind::kImplicitImplicit ? 3.0 : 2.0;
  const double per_region = kRegionSampleBudget / static_cast<double>(std::max<std::size_t>(1, regions.size()));
  const int samples =
      std::clamp(static_cast<int>(std::pow(per_region, 1.0 / power)), 2, tracer.options().start_samples);
  // Regular points only: a sample landing where J_H loses rank is on a curve of singular points
  // (a tangential contact along a curve) or next to a node, which the certified candidates and
  // the singular-point machinery handle; starting there would cut such a curve into pieces that
  // depend on where the samples fell.
  auto take = [&](const VecX& x) {
    if (Problem::rank_ratio(P.linearize(x)) >= kSuspectSingularRankRatio) out->add(x, false);
  };
  for (const UncertainRegion& u : regions)
    for (const VecX& x : find_start_points_in(tracer, u.box, samples, out->stats)) take(x);
  for (const VecX& x : find_start_points(tracer, out->stats)) take(x);
}

}  // namespace

RootSearchResult boundary_roots(const Problem& P, int i, bool upper, const RootSearchOptions& options) {
  for (const System& s : boundary_systems(P))
    if (s.fixed == i &&
        s.at == (upper ? P.bounds()[static_cast<std::size_t>(i)].hi : P.bounds()[static_cast<std::size_t>(i)].lo))
      return in_unknowns(s, find_all_roots(s.equations, s.box, options));
  return {};
}

RootSearchResult trim_face_roots(const Problem& P, int trim, bool upper, const RootSearchOptions& options) {
  const std::vector<System> systems = trim_face_systems(P);
  const std::size_t i = 2 * static_cast<std::size_t>(trim) + (upper ? 1 : 0);
  if (trim < 0 || i >= systems.size()) return {};
  return find_all_roots(systems[i].equations, systems[i].box, options);
}

RootSearchResult turning_points(const Problem& P, int k, const RootSearchOptions& options) {
  System s = turning_system(P, k);
  return find_all_roots(s.equations, s.box, options);
}

std::vector<std::vector<Interval>> singular_point_regions(const Problem& P, long max_boxes) {
  RootSearchOptions ro;
  ro.max_boxes = max_boxes;
  const System s = turning_system(P, 0);
  const RootSearchResult r = find_all_roots(s.equations, s.box, ro);
  std::vector<std::vector<Interval>> regions;
  for (bool budget : {false, true})
    for (const IntervalBox& y : merge_touching(r.undecided, budget)) {
      std::vector<Interval> box;
      for (const IntervalNumber& c : to_unknowns(s, y)) box.push_back({c.lo(), c.hi()});
      regions.push_back(std::move(box));
    }
  return regions;
}

bool evaluates_on_intervals(const Surface& surface) { return interval_refusal(surface).empty(); }

std::string interval_refusal(const Surface& surface) {
  if (surface.get_if<Capsule>()) return "a capsule's pieces are chosen from the midpoint of a box";
  if (const auto* b = surface.get_if<BSplineSurface>()) return b->interval_refusal();
  return "";
}

std::vector<VecX> certified_start_points(const Tracer& tracer, TraceStats* stats, StartPointSearch* search) {
  const auto t0 = std::chrono::steady_clock::now();
  const Problem& P = tracer.problem();
  search->method = StartSearchMethod::kCertified;
  RootSearchOptions ro;
  ro.max_boxes = tracer.options().start_box_budget;
  Collector out{tracer, stats, search, {}, {}};
  // The root searches of the boundary systems and of the first turning system are independent
  // (read-only Problem): run on the shared pool, then taken in the serial order, so the start
  // points are the serial run's.
  std::vector<System> boundary = boundary_systems(P);
  for (System& t : trim_face_systems(P)) boundary.push_back(std::move(t));
  std::vector<System> first{turning_system(P, 0)};
  std::vector<RootSearchResult> found(boundary.size() + 1);
  std::vector<std::optional<VecX>> collapsed(boundary.size());
  for (std::size_t i = 0; i < boundary.size(); ++i)
    collapsed[i] = collapsed_face(P, boundary[i], tracer.options().tolerance);
  // Turning systems go in two passes: each first with a tenth of the budget, so that one that
  // decides at once does not wait behind one that spends the whole budget (a plane across a
  // B-spline half cylinder: the first turning system spent 5,000 boxes, the second decided in 9),
  // then those whose tenth ran out, with all of it (issue 26 item 3).
  RootSearchOptions quick = ro;
  quick.max_boxes = std::max(1L, ro.max_boxes / kTurningFirstPassDivisor);
  parallel_for(found.size(), [&](std::size_t i) {
    if (i < boundary.size() && collapsed[i]) return;
    const System& s = i < boundary.size() ? boundary[i] : first[0];
    found[i] = find_all_roots(s.equations, s.box, i < boundary.size() ? ro : quick);
  });
  bool boundary_decided = true;
  // Progress by systems taken: the boundary ones (solved together above), then at most one turning
  // system per unknown.
  const double systems = static_cast<double>(boundary.size()) + P.dim();
  double solved = static_cast<double>(boundary.size());
  report_progress("start points", solved, systems);
  long saddle_boxes = 0;
  for (std::size_t i = 0; i < boundary.size(); ++i) {
    if (collapsed[i]) {
      out.add(*collapsed[i], true);
      continue;
    }
    const bool decided =
        out.take(boundary[i], found[i]) || decide_clusters(boundary[i], found[i], ro, false, &out, &saddle_boxes);
    if (!decided) out.report(boundary[i], found[i]);
    boundary_decided = decided && boundary_decided;
  }
  // One turning system decided everywhere suffices for the loops; the others' roots still help.
  bool loops_decided = false;
  std::vector<std::pair<System, RootSearchResult>> undecided_turning;
  std::vector<System> retry;  // pass 1's systems whose tenth of the budget ran out
  for (int k = 0; k < P.dim() && !loops_decided; ++k) {
    report_progress("start points", solved++, systems);
    System s = k == 0 ? std::move(first[0]) : turning_system(P, k);
    RootSearchResult r = k == 0 ? std::move(found.back()) : find_all_roots(s.equations, s.box, quick);
    if (std::any_of(r.undecided.begin(), r.undecided.end(), [](const UndecidedBox& u) { return u.budget; })) {
      search->boxes += r.boxes;  // its roots and regions come from the second pass
      retry.push_back(std::move(s));
      continue;
    }
    loops_decided = out.take(s, r) || decide_clusters(s, r, ro, true, &out, &saddle_boxes);
    // Only singular roots left undecided: they are roots of every turning system (J_H loses rank
    // there), so no other k can be decided; their Newton candidates are start points already.
    if (!loops_decided) undecided_turning.emplace_back(std::move(s), std::move(r));
    break;
  }
  // The second pass stops where the first did: at a decided system, or after a singular-only one
  // (the earlier systems still get the whole budget, as they did in one pass).
  for (System& s : retry) {
    if (loops_decided) break;
    RootSearchResult r = find_all_roots(s.equations, s.box, ro);
    loops_decided = out.take(s, r) || decide_clusters(s, r, ro, true, &out, &saddle_boxes);
    const bool singular_only =
        std::none_of(r.undecided.begin(), r.undecided.end(), [](const UndecidedBox& u) { return u.budget; });
    undecided_turning.emplace_back(std::move(s), std::move(r));
    if (singular_only) break;
  }
  report_progress("start points", systems, systems);  // the turning loop may stop early
  if (!loops_decided)
    for (const auto& [s, r] : undecided_turning) out.report(s, r);
  search->certified = boundary_decided && loops_decided;
  if (!search->certified) {
    search->note = std::string(boundary_decided ? "" : "a boundary system ") +
                   (boundary_decided || loops_decided ? "" : "and ") + (loops_decided ? "" : "every turning system ") +
                   "left undecided boxes (uncertain_regions); start points also by sampling them and the domain, "
                   "not every branch is guaranteed";
    add_sampled_starts(&out);
  }
  if (search->certified && saddle_boxes > 0)
    search->note = std::to_string(saddle_boxes) + " singular cluster(s) of a turning system decided as saddle boxes";
  if (search->certified && !out.isolated.empty()) {
    double radius = 0;
    for (const IsolatedBox& b : out.isolated) radius = std::max(radius, b.radius);
    char line[160];
    std::snprintf(line, sizeof line,
                  "%zu isolated point(s) decided by convex boxes: the curve in each lies within %.3g of its point",
                  out.isolated.size(), radius);
    search->note += (search->note.empty() ? "" : "; ") + std::string(line);
  }
  search->time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return std::move(out.points);
}

namespace {

bool multi_piece_bspline(const Surface& s) {
  const auto* b = s.get_if<BSplineSurface>();
  return b && (b->knots_u().size() > 2 * static_cast<std::size_t>(b->degree_u() + 1) ||
               b->knots_v().size() > 2 * static_cast<std::size_t>(b->degree_v() + 1));
}

// Why the certified search is not run on this pair (empty: it is). A B-spline of several pieces
// against another parametric surface is enclosed soundly (surface/piece_enclosure.hpp), but the
// four-unknown turning systems spent the box budget on 12 of the 15 all-NURBS peers cases (2-5 s
// each where sampling takes 30-90 ms, uncertified: a sphere's collapsed pole row is a continuum
// of parameter preimages, a torus or cone pair leaves the whole domain undecided; issue 27 item
// 2, docs/benchmarks.md), so such pairs keep sampling until that search is made effective.
std::string certified_search_refusal(const Problem& P) {
  for (const Surface* s : {&P.first(), &P.second()})
    if (const std::string why = interval_refusal(*s); !why.empty())
      return std::string("a ") + std::string(s->type_name()) + " surface does not evaluate on intervals (" + why + ")";
  if (P.kind() == PairKind::kParametricParametric &&
      (multi_piece_bspline(P.first()) || multi_piece_bspline(P.second())))
    return "the certified search is not run on two parametric surfaces with a B-spline of several pieces (its "
           "four-unknown systems spend the box budget)";
  return "";
}

}  // namespace

std::vector<VecX> automatic_start_points(const Tracer& tracer, TraceStats* stats, StartPointSearch* search) {
  const Problem& P = tracer.problem();
  const std::string refusal = certified_search_refusal(P);
  if (tracer.options().certified_start_points && refusal.empty()) return certified_start_points(tracer, stats, search);
  const auto t0 = std::chrono::steady_clock::now();
  search->method = StartSearchMethod::kSampling;
  search->certified = false;
  if (!tracer.options().certified_start_points)
    search->note = "sampling asked for (certified_start_points = false): not every branch is guaranteed";
  else
    search->note = refusal + ": start points by sampling, not every branch is guaranteed";
  std::vector<VecX> points = find_start_points(tracer, stats);
  search->time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return points;
}

}  // namespace ssimarch
