#include "ssimarch/march/tracer.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <sstream>

#include "ssimarch/core/error.hpp"
#include "ssimarch/geometry/curve_jet.hpp"
#include "ssimarch/march/closest_point.hpp"
#include "ssimarch/march/corrector.hpp"
#include "ssimarch/march/predictor.hpp"
#include "ssimarch/march/step_control.hpp"

namespace ssimarch {

namespace {

// Below this J_H rank ratio a point where the tracer cannot go on is reported as singular.
constexpr double kSingularRankRatio = 1e-4;

double angle_between(const Vec3& a, const Vec3& b) {
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

std::string describe_point(const Vec3& p) {
  std::ostringstream os;
  os.precision(10);
  os << "(" << p.x() << ", " << p.y() << ", " << p.z() << ")";
  return os.str();
}


}  // namespace

double arc_length_estimate(const Vec3& a, const Vec3& ta, const Vec3& b, const Vec3& tb) {
  double c = (b - a).norm();
  double phi = angle_between(ta, tb);
  if (phi < 1e-8) return c;
  return c * (phi / 2) / std::sin(phi / 2);
}

Tracer::Tracer(const Problem& problem, TraceOptions options) : problem_(problem), options_(options) {
  std::string error;
  if (!options_.is_valid(&error)) throw InputError("options", error);
  const bool adaptive = options_.step != StepRule::kConstant;
  // Spacing used to tell curves and start points apart: the user's step, else the constant
  // rule's automatic step (scale/100), whatever the rule.
  spacing_ = options_.step_length > 0 ? options_.step_length : problem_.scale() / 100.0;
  if (options_.step_length == 0) options_.step_length = problem_.scale() / (adaptive ? 10.0 : 100.0);
  if (options_.min_step_length == 0) options_.min_step_length = 1e-3 * options_.step_length;
  if (options_.min_step == 0) options_.min_step = 1e-7 * options_.step_length;
  options_.min_step = std::min(options_.min_step, options_.min_step_length);
  if (options_.deviation == 0) options_.deviation = 1e-4 * problem_.scale();
}

namespace {
void add_evaluations(TraceStats* stats, const std::array<long, 2>& e) {
  stats->surface_evaluations[0] += e[0];
  stats->surface_evaluations[1] += e[1];
}
}  // namespace

Tracer::Branch Tracer::march(const CurvePoint& start, bool detect_closure, TraceStats* stats) const {
  const Problem& P = problem_;
  const TraceOptions& o = options_;
  Branch b;
  b.points.push_back(start);
  AnyPredictor predictor = make_predictor(o);
  AnyCorrector corrector = make_corrector(o);
  AnyStepControl step = make_step_control(o);
  const int order = std::max(jet_order(predictor), std::visit([](const auto& s) { return s.jet_order(); }, step));
  const std::array<long, 2> jet_cost = jet_evaluation_cost(P, order);
  CorrectorOptions co{o.tolerance, o.max_corrector_iterations};

  MarchState state;
  state.map_tolerance = o.tolerance;
  state.here = curve_jet_dynamic(P, start.x, order, &start.t);
  stats->jet_evaluations += order;
  add_evaluations(stats, jet_cost);
  CurvePoint cur = start;
  if (state.here.status != CurveJetStatus::kOk) {
    b.why = Termination::kSingularPoint;
    b.message = "the start point " + describe_point(start.p) + " is a singular point of the curve";
    return b;
  }
  std::visit([&](auto& s) { s.start(curve_frame(state.here, P.scale())); }, step);
  const double sagitta_slack = 1e-8 * P.scale() + 10 * o.tolerance;

  while (true) {
    if (static_cast<long>(b.points.size()) >= o.max_points) {
      b.why = Termination::kMaxPoints;
      b.message = "reached max_points = " + std::to_string(o.max_points);
      return b;
    }
    if (b.length >= o.max_length) {
      b.why = Termination::kMaxLength;
      b.message = "reached max_length";
      return b;
    }
    const double h = std::visit([](const auto& s) { return s.step(); }, step);
    Prediction pr = predict(predictor, P, state, h);
    add_evaluations(stats, pr.evaluations);
    if (pr.fallback) ++stats->predictor_fallbacks;
    const double arc = pr.arc > 0 ? pr.arc : h;
    CorrectorResult cr = correct(corrector, P, pr.x, co);
    stats->linearizations += cr.linearizations;
    add_evaluations(stats, cr.evaluations);
    bool ok = cr.status == CorrectorStatus::kConverged;
    bool measured = false;
    StepReport report;
    DynamicCurveJet next;
    Vec3 p1;
    if (ok) {
      p1 = P.point(cr.x);
      if (P.kind() != PairKind::kImplicitImplicit) ++stats->surface_evaluations[0];
      double chord = (p1 - cur.p).norm();
      ok = chord >= 0.25 * arc && chord <= 1.75 * arc && (p1 - pr.point).norm() <= o.max_correction_ratio * arc &&
           (p1 - cur.p).dot(cur.t) > 0;
      if (ok) {
        next = curve_jet_dynamic(P, cr.x, order, &cur.t);
        stats->jet_evaluations += order;
        add_evaluations(stats, jet_cost);
        ok = next.status == CurveJetStatus::kOk && angle_between(cur.t, next.tangent()) <= o.max_turn_angle;
        if (ok) {
          report = make_step_report(cur.p, cur.t, p1, next.tangent(), pr.point, arc, cr.iterations);
          measured = true;
          ok = std::visit([&](const auto& s) { return s.acceptable(report); }, step);
        }
      }
    } else {
      ++stats->corrector_failures;
    }
    if (!ok) {
      ++stats->rejected_steps;
      if (!std::visit([&](auto& s) { return s.rejected(measured ? &report : nullptr); }, step)) {
        Linearization L = P.linearize(cur.x);
        add_evaluations(stats, linearize_evaluation_cost(P));
        double sin_theta = L.normal_first.cross(L.normal_second).norm();
        b.why = state.here.rank_ratio < kSingularRankRatio || sin_theta < kSingularRankRatio
                    ? Termination::kSingularPoint
                    : Termination::kStepUnderflow;
        std::ostringstream os;
        os.precision(3);
        os << "no step >= " << o.min_step << " could be taken after " << describe_point(cur.p)
           << "; Jacobian rank ratio " << state.here.rank_ratio << ", sin(angle between normals) " << sin_theta;
        b.message = os.str();
        return b;
      }
      continue;
    }

    // Domain edge: land exactly on the first bound the chord crosses.
    if (!P.inside(cr.x)) {
      VecX delta = cr.x - cur.x;
      int edge = -1;
      double fraction = 2, value = 0;
      for (int i = 0; i < P.dim(); ++i) {
        if (P.periods()[static_cast<std::size_t>(i)] > 0 || delta[i] == 0) continue;
        const Interval& iv = P.bounds()[static_cast<std::size_t>(i)];
        for (double bound : {iv.lo, iv.hi}) {
          double f = (bound - cur.x[i]) / delta[i];
          if (f >= 0 && f <= 1 && f < fraction) {
            fraction = f;
            edge = i;
            value = bound;
          }
        }
      }
      b.why = Termination::kLeftDomain;
      if (edge < 0) {
        b.message = "left the domain";
        return b;
      }
      CorrectorResult landed = solve_with_fixed_unknown(P, cur.x + fraction * delta, edge, value, co);
      stats->linearizations += landed.linearizations;
      add_evaluations(stats, landed.evaluations);
      std::string name = P.unknown_names()[static_cast<std::size_t>(edge)];
      if (landed.status != CorrectorStatus::kConverged || !P.inside(landed.x, 1e-9 * (1 + std::fabs(value)))) {
        b.message = "left the domain at " + name + " = " + std::to_string(value) + " (could not land on the edge)";
        return b;
      }
      Vec3 pe = P.point(landed.x);
      if ((pe - cur.p).norm() > 1e-12 * P.scale()) {
        DynamicCurveJet ej = curve_jet_dynamic(P, landed.x, 1, &cur.t);
        ++stats->jet_evaluations;
        add_evaluations(stats, jet_evaluation_cost(P, 1));
        Vec3 te = ej.status == CurveJetStatus::kOk ? ej.tangent() : Vec3((pe - cur.p).normalized());
        b.length += arc_length_estimate(cur.p, cur.t, pe, te);
        b.points.push_back({landed.x, pe, te});
        stats->record_iterations(landed.iterations);
        ++stats->points;
      }
      b.message = "reached the domain edge " + name + " = " + std::to_string(value);
      return b;
    }

    // Closure: the start lies on this chord, within twice its sagitta, tangents agreeing.
    if (detect_closure && b.points.size() >= 3) {
      Vec3 seg = p1 - cur.p;
      double tau = (start.p - cur.p).dot(seg) / seg.squaredNorm();
      if (tau >= 0 && tau <= 1) {
        double dist = (start.p - (cur.p + tau * seg)).norm();
        double phi = angle_between(cur.t, next.tangent());
        double sagitta = 0.5 * seg.norm() * std::tan(phi / 4);
        if (dist <= 2 * sagitta + sagitta_slack && start.t.dot(cur.t) > 0.5) {
          b.length += arc_length_estimate(cur.p, cur.t, start.p, start.t);
          b.points.push_back(start);
          b.why = Termination::kClosedLoop;
          b.message = "closed loop";
          return b;
        }
      }
    }

    stats->record_iterations(cr.iterations);
    ++stats->points;
    b.length += arc_length_estimate(cur.p, cur.t, p1, next.tangent());
    state.has_previous = true;
    state.previous_x = cur.x;
    state.previous_p = cur.p;
    state.previous_t = cur.t;
    state.circle_line_parameter = pr.circle_line_parameter;
    state.circle_line_axis = pr.circle_line_axis;
    cur = CurvePoint{cr.x, p1, next.tangent()};
    state.here = std::move(next);
    b.points.push_back(cur);
    const CurveFrame frame = curve_frame(state.here, P.scale());
    std::visit([&](auto& s) { s.accepted(report, frame); }, step);
  }
}

TracedCurve Tracer::trace_from(const VecX& x0, TraceStats* stats) const {
  TracedCurve curve;
  DynamicCurveJet j = curve_jet_dynamic(problem_, x0, 1);
  ++stats->jet_evaluations;
  add_evaluations(stats, jet_evaluation_cost(problem_, 1));
  CurvePoint start{x0, problem_.point(x0), j.tangent()};
  if (j.status != CurveJetStatus::kOk) {
    curve.points.push_back(start);
    curve.start_end = curve.end_end = Termination::kSingularPoint;
    curve.start_message = curve.end_message = "the start point " + describe_point(start.p) + " is a singular point";
    return curve;
  }
  ++stats->points;
  stats->record_iterations(1);
  Branch forward = march(start, true, stats);
  if (forward.why == Termination::kClosedLoop) {
    curve.points = std::move(forward.points);
    curve.closed = true;
    curve.length = forward.length;
  } else {
    CurvePoint reversed{x0, start.p, -start.t};
    Branch backward = march(reversed, false, stats);
    for (auto it = backward.points.rbegin(); it != backward.points.rend(); ++it)
      curve.points.push_back({it->x, it->p, -it->t});
    curve.points.insert(curve.points.end(), forward.points.begin() + 1, forward.points.end());
    curve.length = forward.length + backward.length;
    curve.start_end = backward.why;
    curve.start_message = backward.message;
  }
  curve.end_end = forward.why;
  curve.end_message = forward.message;
  for (auto& p : curve.points) p.x = problem_.wrap(p.x);
  return curve;
}

bool Tracer::on_traced_curve(const Vec3& p, const std::vector<TracedCurve>& curves) const {
  const double radius = 0.2 * spacing_;
  for (const auto& c : curves)
    for (std::size_t i = 0; i + 1 < c.points.size(); ++i) {
      Vec3 a = c.points[i].p, seg = c.points[i + 1].p - a;
      double L2 = seg.squaredNorm();
      double tau = L2 > 0 ? std::clamp((p - a).dot(seg) / L2, 0.0, 1.0) : 0.0;
      if ((p - (a + tau * seg)).norm() <= radius) return true;
    }
  return false;
}

std::vector<VecX> Tracer::find_start_points(TraceStats* stats) const {
  const Problem& P = problem_;
  NewtonCorrector corrector;
  CorrectorOptions co{options_.tolerance, 20};
  std::vector<VecX> found;
  std::vector<Vec3> found_points;
  const double separation = 0.5 * spacing_;
  auto consider = [&](const VecX& guess) {
    CorrectorResult r = corrector.correct(P, guess, co);
    stats->linearizations += r.linearizations;
    add_evaluations(stats, r.evaluations);
    if (r.status != CorrectorStatus::kConverged || !P.inside(r.x)) return;
    Vec3 p = P.point(r.x);
    for (const Vec3& q : found_points)
      if ((q - p).norm() < separation) return;
    found.push_back(r.x);
    found_points.push_back(p);
  };
  const int n = options_.start_samples;
  auto sample = [&](const Interval& iv, int i, int count) { return iv.lo + iv.width() * (i + 0.5) / count; };
  switch (P.kind()) {
    case PairKind::kParametricImplicit:
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          VecX x(2);
          x << sample(P.bounds()[0], i, n), sample(P.bounds()[1], j, n);
          consider(x);
        }
      break;
    case PairKind::kImplicitImplicit: {
      int m = std::min(n, 16);
      for (int i = 0; i < m; ++i)
        for (int j = 0; j < m; ++j)
          for (int k = 0; k < m; ++k) {
            VecX x(3);
            x << sample(P.bounds()[0], i, m), sample(P.bounds()[1], j, m), sample(P.bounds()[2], k, m);
            consider(x);
          }
      break;
    }
    case PairKind::kParametricParametric: {
      // Pair each sample of F with the nearest sample of G, then correct.
      std::vector<Vec3> gp;
      std::vector<Vec2> guv;
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          double p = sample(P.bounds()[2], i, n), q = sample(P.bounds()[3], j, n);
          Vec3T<double> g = P.second().point(p, q);
          gp.emplace_back(g.x, g.y, g.z);
          guv.emplace_back(p, q);
        }
      for (int i = 0; i < n; ++i)
        for (int j = 0; j < n; ++j) {
          double u = sample(P.bounds()[0], i, n), v = sample(P.bounds()[1], j, n);
          Vec3T<double> f = P.first().point(u, v);
          Vec3 fp(f.x, f.y, f.z);
          std::size_t best = 0;
          double bd = std::numeric_limits<double>::infinity();
          for (std::size_t k = 0; k < gp.size(); ++k) {
            double d = (gp[k] - fp).squaredNorm();
            if (d < bd) {
              bd = d;
              best = k;
            }
          }
          VecX x(4);
          x << u, v, guv[best][0], guv[best][1];
          consider(x);
        }
      break;
    }
  }
  return found;
}

TraceResult Tracer::trace(const std::vector<Vec3>& starts) const {
  auto t0 = std::chrono::steady_clock::now();
  TraceResult result;
  std::vector<VecX> seeds;
  if (starts.empty()) {
    seeds = find_start_points(&result.stats);
  } else {
    NewtonCorrector corrector;
    CorrectorOptions co{options_.tolerance, 30};
    for (const Vec3& X : starts) {
      auto x = unknowns_near(problem_, X);
      CorrectorResult r;
      if (x) {
        r = corrector.correct(problem_, *x, co);
        result.stats.linearizations += r.linearizations;
        add_evaluations(&result.stats, r.evaluations);
      }
      if (!x || r.status != CorrectorStatus::kConverged) {
        ++result.failed_starts;
        result.warnings.push_back("start point " + describe_point(X) + " could not be moved onto the intersection (corrector " +
                                  std::string(x ? to_string(r.status) : "had no initial guess") + ")");
        continue;
      }
      seeds.push_back(r.x);
    }
  }
  for (VecX& x : seeds) {
    // A start point that converged onto a singular point (e.g. Newton from far away ending at a
    // node) is moved to a regular point of the curve next to it, which the trace then crosses.
    if (Problem::rank_ratio(problem_.linearize(x)) < 1e-4) {
      if (auto y = regular_point_near(problem_, x, 0.5 * options_.step_length, options_.tolerance)) {
        result.warnings.push_back("start point " + describe_point(problem_.point(x)) +
                                  " is a singular point of the curve; tracing from the regular point " +
                                  describe_point(problem_.point(*y)) + " next to it");
        x = *y;
      }
    }
    if (on_traced_curve(problem_.point(x), result.curves)) continue;
    result.curves.push_back(trace_from(x, &result.stats));
  }
  result.stats.time_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
  return result;
}

}  // namespace ssimarch
