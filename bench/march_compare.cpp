// The marching comparison of docs/benchmarks.md ("Marching"): every predictor x step rule on the
// seeds' surface pairs, at one chordal deviation delta, against a fine reference trace.
//
//   make bench-march        (or: cmake --preset bench && cmake --build build-bench --target march_compare
//                            && build-bench/bin/march_compare > out/march_compare.md)
//
// Options: --delta D (default 1e-3, model units), --reps N (timing repetitions, default 3),
// --pair NAME (only that pair), --summary (only the aggregate tables).
//
// Per run: points, rejected steps, corrector iteration histogram (1, 2, 3, 4, >= 5), share of
// points in <= 2 iterations, max residual (Linearization::distance over the points), max distance
// of segment midpoints from the curve (divided by delta), points over the minimum
// N_min = integral of sqrt(kappa / (8 delta)) ds, surface evaluations, wall time (best of reps),
// and whether the trace is the reference curve (closed as it, same length to 1e-4, every point
// within 1e-7 of it): "jump" otherwise.
//
// Distances from the curve: the nearest point of a reference trace (taylor-6 predictor, constant
// step 0.004, tolerance 1e-13), then the minimum of |alpha(s) - X| over the curve's exact
// 4th-order jet at that point (error ~ 0.004^5).
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <unordered_map>
#include <vector>

#include "ssimarch/expr/program.hpp"
#include "ssimarch/march/predictor.hpp"
#include "ssimarch/trace/trace_all.hpp"
#include "ssimarch/surface/sphere.hpp"
#include "ssimarch/surface/surface.hpp"
#include "testing/surface_pairs.hpp"

using namespace ssimarch;

namespace {

using testing::parametric;

struct Pair {
  std::string name;
  std::string source;
  Problem problem;
  Vec3 start;
};

std::vector<Pair> pairs() {
  const double pi = M_PI;
  std::vector<Pair> r;
  r.push_back({"ruled-torus", "thesis pair 1 (ch. 3/4), PP",
               Problem(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric),
               Vec3(5, 0, 0)});
  r.push_back({"sphere-cylinder", "Viviani (thesis pair 2 / seed 004), PI, node at (0,-2,0)",
               Problem(testing::cylinder_f2(), Sphere(Vec3::Zero(), 2.0),
                       PairKind::kParametricImplicit),
               Vec3(1, -1, std::sqrt(2.0))});
  r.push_back({"plane-ellipsoid", "seed 000 ex. 4, PP",
               Problem(parametric("u", "v", "u-v+1", {-3, 3}, {-3, 3}),
                       parametric("cos(v)*cos(u)", "2*sin(v)*cos(u)", "3*sin(u)", {-pi / 2, pi / 2}, {0, 2 * pi}, false, true),
                       PairKind::kParametricParametric),
               Vec3(0.8, 0, 1.8)});
  r.push_back({"two-cylinders", "seed 000 ex. 5 (trigonometric parameterisation), PP, nodes at (0,+-1,0)",
               Problem(parametric("u", "cos(v)", "sin(v)", {-1.5, 1.5}, {0, 2 * pi}, false, true),
                       parametric("cos(v)", "sin(v)", "u", {-1.5, 1.5}, {0, 2 * pi}, false, true), PairKind::kParametricParametric),
               Vec3(1, 0, 1)});
  r.push_back({"paraboloid-cylinder", "seed 000 ex. 3 (corrected G), PP, planar circle",
               Problem(parametric("u", "v", "u^2+v^2", {-3, 3}, {-3, 3}),
                       parametric("2*cos(u)", "2*sin(u)", "v", {0, 2 * pi}, {0, 6}, true, false), PairKind::kParametricParametric),
               Vec3(1.3993, 1.4289, 4.0)});
  r.push_back({"helicoid-cylinder", "thesis Fig. 4.5a (formulas ours), PP, open",
               Problem(parametric("u*cos(v)", "u*sin(v)", "0.5*v", {0, 3}, {0, 4 * pi}),
                       parametric("0.5+cos(u)", "sin(u)", "v", {0, 2 * pi}, {-2, 8}, true, false), PairKind::kParametricParametric),
               Vec3(0.6361, 0.9907, 0.5)});
  r.push_back({"paraboloid-sine", "thesis Fig. 4.4b (data of thesis ex. 39), PP",
               Problem(parametric("u", "v", "u^2/3+v^2/3-9", {-6, 6}, {-6, 6}), parametric("u", "v", "sin(v)-3", {-6, 6}, {-6, 6}),
                       PairKind::kParametricParametric),
               Vec3(4.2426, 0, -3)});
  r.push_back({"paraboloid-saddle", "thesis Fig. 4.5b (formulas ours), PP, almost planar",
               Problem(parametric("u", "v", "u^2+v^2", {-2, 2}, {-2, 2}), parametric("u", "v", "1+0.1*(u^2-v^2)", {-2, 2}, {-2, 2}),
                       PairKind::kParametricParametric),
               Vec3(1.0541, 0, 1.1111)});
  r.push_back({"ellipsoid-ellipsoid", "thesis ex. 17 (Fig. 4.6 kind), PP, nodes at (0,+-1.6,0)",
               Problem(parametric("1.2*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2*cos(v)", {0, 2 * pi}, {0, pi}, true, false),
                       parametric("0.9*cos(u)*sin(v)", "1.6*sin(u)*sin(v)", "2.5*cos(v)", {0, 2 * pi}, {0, pi}, true, false),
                       PairKind::kParametricParametric),
               Vec3(0.675, 0, 1.654)});
  return r;
}

// --- reference curve -------------------------------------------------------------------------------

class Reference {
 public:
  Reference(const Problem& P, const Vec3& start) : P_(P) {
    TraceOptions o;
    o.predictor = PredictorKind::kTaylor;
    o.taylor_order = 6;
    o.step = StepRule::kConstant;
    o.step_length = kH;
    o.tolerance = 1e-13;
    TraceResult r = trace_all(P, o, {start});
    if (r.curves.size() != 1) {
      std::fprintf(stderr, "reference trace failed\n");
      std::exit(1);
    }
    curve_ = r.curves[0];
    for (std::size_t i = 0; i < curve_.points.size(); ++i) grid_[key(curve_.points[i].p)].push_back(i);
    jets_.resize(curve_.points.size());
    for (std::size_t i = 0; i + 1 < curve_.points.size(); ++i) {
      const double ds = arc_length_estimate(curve_.points[i].p, curve_.points[i].t, curve_.points[i + 1].p, curve_.points[i + 1].t);
      const double k0 = kappa(i), k1 = kappa(i + 1);
      root_kappa_integral_ += 0.5 * (std::sqrt(k0) + std::sqrt(k1)) * ds;
      mean_kappa_ += 0.5 * (k0 + k1) * ds;
      max_kappa_ = std::max({max_kappa_, k0, k1});
    }
    mean_kappa_ /= curve_.length;
  }

  const TracedCurve& curve() const { return curve_; }
  double min_points(double delta) const { return root_kappa_integral_ / std::sqrt(8 * delta); }
  double mean_kappa() const { return mean_kappa_; }
  double max_kappa() const { return max_kappa_; }

  /// Distance from X to the curve (X within a few kH of it; +inf if no reference point is near):
  /// the least over the kCandidates nearest reference points of the distance from their local
  /// jets (several, because next to a node the nearest point may lie on the other branch).
  double distance(const Vec3& X) const {
    std::vector<std::pair<double, std::size_t>> near;
    const long cx = cell(X.x()), cy = cell(X.y()), cz = cell(X.z());
    // Grow the searched cube until it holds reference points, then one ring more (the nearest
    // point may sit in the next ring).
    for (long r = 1, found_at = -1; r <= 256 && (found_at < 0 || r <= found_at + 1); r *= 2) {
      near.clear();
      for (long i = -r; i <= r; ++i)
        for (long j = -r; j <= r; ++j)
          for (long k = -r; k <= r; ++k) {
            auto it = grid_.find(pack(cx + i, cy + j, cz + k));
            if (it == grid_.end()) continue;
            for (std::size_t n : it->second) near.emplace_back((curve_.points[n].p - X).norm(), n);
          }
      if (!near.empty() && found_at < 0) found_at = r;
    }
    if (near.empty()) return std::numeric_limits<double>::infinity();
    const std::size_t m = std::min<std::size_t>(kCandidates, near.size());
    std::partial_sort(near.begin(), near.begin() + static_cast<long>(m), near.end());
    double best = near[0].first;
    for (std::size_t c = 0; c < m; ++c) best = std::min(best, jet_distance(near[c].second, X));
    return best;
  }

 private:
  static constexpr int kCandidates = 6;
  double jet_distance(std::size_t n, const Vec3& X) const {
    const DynamicCurveJet& J = jet(n);
    if (J.status != CurveJetStatus::kOk) return (curve_.points[n].p - X).norm();
    double s = 0;
    for (int it = 0; it < 30; ++it) {
      Vec3 a = J.alpha_at(s), d1 = Vec3::Zero(), d2 = Vec3::Zero();
      for (int k = J.order; k >= 1; --k) d1 = d1 * s + k * J.alpha[static_cast<std::size_t>(k)];
      for (int k = J.order; k >= 2; --k) d2 = d2 * s + k * (k - 1) * J.alpha[static_cast<std::size_t>(k)];
      double g = d1.dot(a - X), gp = d2.dot(a - X) + d1.squaredNorm();
      double step = g / gp;
      s = std::clamp(s - step, -2 * kH, 2 * kH);
      if (std::fabs(step) < 1e-17) break;
    }
    return (J.alpha_at(s) - X).norm();
  }
  static constexpr double kH = 0.004;
  static constexpr double kCell = 4 * kH;
  static long cell(double x) { return static_cast<long>(std::floor(x / kCell)); }
  static long long pack(long a, long b, long c) { return ((a + 100000LL) * 200001LL + (b + 100000LL)) * 200001LL + (c + 100000LL); }
  static long long key(const Vec3& p) { return pack(cell(p.x()), cell(p.y()), cell(p.z())); }
  const DynamicCurveJet& jet(std::size_t i) const {
    if (!jets_[i]) jets_[i] = curve_jet_dynamic(P_, curve_.points[i].x, 4, &curve_.points[i].t);
    return *jets_[i];
  }
  double kappa(std::size_t i) const { return jet(i).status == CurveJetStatus::kOk ? 2 * jet(i).alpha[2].norm() : 0.0; }

  const Problem& P_;
  TracedCurve curve_;
  std::unordered_map<long long, std::vector<std::size_t>> grid_;
  mutable std::vector<std::optional<DynamicCurveJet>> jets_;
  double root_kappa_integral_ = 0, mean_kappa_ = 0, max_kappa_ = 0;
};

// --- runs ------------------------------------------------------------------------------------------

struct Row {
  std::string pair, predictor, rule;
  long points = 0, rejected = 0;
  std::array<long, 5> hist{};
  double le2 = 0, residual = 0, midpoint = 0, ratio = 0, time_ms = 0;
  std::array<long, 2> evals{};
  long fallbacks = 0;
  bool ok = false;
  std::string why;
};

TraceOptions options_for(PredictorKind p, StepRule s, double delta, const Reference& ref) {
  TraceOptions o;
  o.predictor = p;
  o.step = s;
  o.tolerance = 1e-12;
  o.deviation = delta;
  switch (s) {
    case StepRule::kConstant: o.step_length = std::sqrt(8 * delta / ref.max_kappa()); break;  // sagitta <= delta everywhere
    case StepRule::kAngular: o.turn_angle = std::min(1.0, std::sqrt(8 * delta * ref.mean_kappa())); break;
    case StepRule::kDeviation: o.deviation = 4 * delta; break;  // Stoyanov's D ~ kappa L^2/2 = 4 sagitta
    case StepRule::kOrder3: o.deviation = delta; break;
    case StepRule::kChordal: break;
  }
  return o;
}

Row run(const Pair& pair, const Reference& ref, PredictorKind p, StepRule s, double delta, int reps) {
  Row row;
  row.pair = pair.name;
  row.predictor = std::string(to_string(p));
  row.rule = std::string(to_string(s));
  TraceOptions o = options_for(p, s, delta, ref);
  TraceResult r;
  double best = std::numeric_limits<double>::infinity();
  for (int i = 0; i < reps; ++i) {
    r = trace_all(pair.problem, o, {pair.start});
    best = std::min(best, r.stats.time_ms);
  }
  row.time_ms = best;
  row.points = r.stats.points;
  row.rejected = r.stats.rejected_steps;
  row.hist = r.stats.iterations;
  long total = 0;
  for (long h : row.hist) total += h;
  row.le2 = total > 0 ? double(row.hist[0] + row.hist[1]) / double(total) : 0;
  row.evals = r.stats.surface_evaluations;
  row.fallbacks = r.stats.predictor_fallbacks;
  if (r.curves.size() != 1) {
    row.why = std::to_string(r.curves.size()) + " curves";
    return row;
  }
  const TracedCurve& c = r.curves[0];
  const TracedCurve& rc = ref.curve();
  double worst_point = 0;
  for (std::size_t i = 0; i < c.points.size(); ++i) {
    row.residual = std::max(row.residual, pair.problem.linearize(c.points[i].x).distance);
    worst_point = std::max(worst_point, ref.distance(c.points[i].p));
    if (i + 1 < c.points.size()) row.midpoint = std::max(row.midpoint, ref.distance(0.5 * (c.points[i].p + c.points[i + 1].p)));
  }
  const double segments = static_cast<double>(c.points.size() - 1);
  row.ratio = segments / ref.min_points(delta);
  row.ok = c.closed == rc.closed && std::fabs(c.length / rc.length - 1) < 1e-4 && worst_point < 1e-7;
  if (!row.ok) {
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s, length %.6g vs %.6g, off by %.1e", c.closed ? "closed" : to_string(c.end_end).data(),
                  c.length, rc.length, worst_point);
    row.why = buf;
  }
  return row;
}

std::string pct(long n, long total) {
  char b[16];
  std::snprintf(b, sizeof b, "%.0f", total > 0 ? 100.0 * double(n) / double(total) : 0.0);
  return b;
}

void print_row(const Row& r, bool with_pair) {
  long total = 0;
  for (long h : r.hist) total += h;
  std::printf("| %s%s | %s | %ld | %ld | %s/%s/%s/%s/%s | %.0f | %.1e | %.2f | %.2f | %ld/%ld | %.2f | %s |\n",
              with_pair ? (r.pair + " | ").c_str() : "", r.predictor.c_str(), r.rule.c_str(), r.points, r.rejected,
              pct(r.hist[0], total).c_str(), pct(r.hist[1], total).c_str(), pct(r.hist[2], total).c_str(),
              pct(r.hist[3], total).c_str(), pct(r.hist[4], total).c_str(), 100 * r.le2, r.residual, r.midpoint / 1.0,
              r.ratio, r.evals[0], r.evals[1], r.time_ms, r.ok ? "ok" : ("**jump**: " + r.why).c_str());
}

}  // namespace

int main(int argc, char** argv) {
  double delta = 1e-3;
  int reps = 3;
  std::string only;
  bool summary_only = false;
  for (int i = 1; i < argc; ++i) {
    std::string a = argv[i];
    if (a == "--delta" && i + 1 < argc) delta = std::atof(argv[++i]);
    else if (a == "--reps" && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
    else if (a == "--pair" && i + 1 < argc) only = argv[++i];
    else if (a == "--summary") summary_only = true;
    else {
      std::fprintf(stderr, "usage: march_compare [--delta D] [--reps N] [--pair NAME] [--summary]\n");
      return 2;
    }
  }
  if (!(delta > 0)) {
    std::fprintf(stderr, "march_compare: --delta must be > 0\n");
    return 2;
  }
  const PredictorKind predictors[] = {PredictorKind::kTangent,  PredictorKind::kCircle,     PredictorKind::kCircleWuAndrade,
                                      PredictorKind::kParabola, PredictorKind::kPolynomial, PredictorKind::kHelix,
                                      PredictorKind::kTaylor};
  const StepRule rules[] = {StepRule::kConstant, StepRule::kAngular, StepRule::kDeviation, StepRule::kOrder3, StepRule::kChordal};

  std::printf("# march_compare: delta = %g (model units), corrector newton, tolerance 1e-12, best of %d runs\n\n", delta, reps);
  std::vector<Row> rows;
  for (const Pair& pair : pairs()) {
    if (!only.empty() && pair.name != only) continue;
    Reference ref(pair.problem, pair.start);
    if (!summary_only) {
      std::printf("## %s — %s\n\nreference: %s, length %.10g, %zu points; kappa mean %.4g, max %.4g; N_min = %.1f\n\n",
                  pair.name.c_str(), pair.source.c_str(), ref.curve().closed ? "closed" : "open", ref.curve().length,
                  ref.curve().points.size(), ref.mean_kappa(), ref.max_kappa(), ref.min_points(delta));
      std::printf("| predictor | step | points | rejected | iterations 1/2/3/4/>=5 %% | <=2 %% | max residual | max midpoint dist / delta | N / N_min | evaluations F/G | ms | result |\n");
      std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
    }
    for (PredictorKind p : predictors)
      for (StepRule s : rules) {
        Row r = run(pair, ref, p, s, delta, reps);
        r.midpoint /= delta;
        if (!summary_only) print_row(r, false);
        rows.push_back(r);
      }
    if (!summary_only) std::printf("\n");
    std::fflush(stdout);
  }

  // Aggregate over pairs: totals and worst cases per predictor x step rule.
  std::printf("## Summary over all pairs\n\n");
  std::printf("| predictor | step | points | rejected | <=2 it %% | worst midpoint / delta | worst N / N_min | evaluations F+G | ms | jumps |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|\n");
  for (PredictorKind p : predictors)
    for (StepRule s : rules) {
      long points = 0, rejected = 0, le2 = 0, all = 0, evals = 0, jumps = 0;
      double worst_mid = 0, worst_ratio = 0, ms = 0;
      for (const Row& r : rows) {
        if (r.predictor != to_string(p) || r.rule != to_string(s)) continue;
        points += r.points;
        rejected += r.rejected;
        for (long h : r.hist) all += h;
        le2 += r.hist[0] + r.hist[1];
        evals += r.evals[0] + r.evals[1];
        worst_mid = std::max(worst_mid, r.midpoint);
        worst_ratio = std::max(worst_ratio, r.ratio);
        ms += r.time_ms;
        jumps += r.ok ? 0 : 1;
      }
      std::printf("| %s | %s | %ld | %ld | %s | %.2f | %.2f | %ld | %.1f | %ld |\n", std::string(to_string(p)).c_str(),
                  std::string(to_string(s)).c_str(), points, rejected, pct(le2, all).c_str(), worst_mid, worst_ratio, evals, ms,
                  jumps);
    }
  return 0;
}
