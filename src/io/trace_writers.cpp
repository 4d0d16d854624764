#include "ssimarch/io/trace_writers.hpp"

#include <charconv>
#include <cmath>
#include <iomanip>

#include "ssimarch/io/json_vectors.hpp"
#include "ssimarch/io/singular_json.hpp"
#include "ssimarch/io/topology_json.hpp"
#include "ssimarch/march/tracer.hpp"
namespace ssimarch {

using nlohmann::json;

namespace {
json end_json(Termination t, const std::string& message) {
  return json{{"reason", std::string(to_string(t))}, {"message", message}};
}
// Shortest decimal that reads back to the same double.
std::string shortest(double x) {
  char buf[64];
  auto r = std::to_chars(buf, buf + sizeof buf, x);
  return std::string(buf, r.ptr);
}
// The curve's differential geometry at a point; quantities a method cannot determine are null.
void add_geometry(const CurveGeometry& g, json* point) {
  auto v = [](const Vec3& a) { return a.allFinite() ? json::array({a.x(), a.y(), a.z()}) : json(nullptr); };
  auto s = [](double x) { return std::isfinite(x) ? json(x) : json(nullptr); };
  (*point)["t"] = v(g.t);
  (*point)["n"] = v(g.n);
  (*point)["b"] = v(g.b);
  (*point)["kappa"] = s(g.kappa);
  (*point)["tau"] = s(g.tau);
  (*point)["kappa_prime"] = s(g.kappa_prime);
  (*point)["theta"] = s(g.theta);
  (*point)["geometry_status"] = std::string(to_string(g.status));
}
json bspline_json(const BSplineCurve& b) {
  json cps = json::array();
  for (const VecX& c : b.control_points) cps.push_back(vector_json(c));
  return json{{"degree", b.degree}, {"periodic", b.periodic}, {"knots", b.knots}, {"control_points", std::move(cps)}};
}
// The curve's certified B-spline, its p-curves (named by surface) and the measured bound.
void add_spline(const CurveSpline& s, const std::array<std::string, 2>& parametric, json* curve) {
  json b = bspline_json(s.curve);
  b["tolerance"] = s.tolerance;
  b["within_tolerance"] = s.within_tolerance;
  b["pieces"] = s.pieces;
  b["inserted_points"] = s.inserted_points;
  b["c0_knots"] = s.c0_knots;
  b["c1_knots"] = s.c1_knots;
  b["time_ms"] = s.time_ms;
  (*curve)["bspline"] = std::move(b);
  json pcurves = json::array();
  for (std::size_t k = 0; k < s.pcurves.size(); ++k) {
    json p = bspline_json(s.pcurves[k]);
    p["surface"] = parametric[k];
    pcurves.push_back(std::move(p));
  }
  (*curve)["pcurves"] = std::move(pcurves);
  (*curve)["max_deviation"] = s.max_deviation;
}

// The exact conic of a closed-form curve (analytic/conic.hpp): its parameterisation is
// centre + a cos t axes[0] + b sin t axes[1] (circle, ellipse), ... (docs/output-format.md).
json conic_to_json(const Conic& c) {
  return json{{"type", std::string(to_string(c.type))},
              {"center", vector_json(c.center)},
              {"axes", json::array({vector_json(c.e0), vector_json(c.e1)})},
              {"semi_axes", json::array({c.a, c.b})},
              {"parameter_range", json::array({c.range.lo, c.range.hi})},
              {"contact", std::string(to_string(c.contact))}};
}
}  // namespace

json stats_to_json(const TraceStats& s) {
  return json{{"points", s.points},
              {"rejected_steps", s.rejected_steps},
              {"iterations",
               {{"1", s.iterations[0]}, {"2", s.iterations[1]}, {"3", s.iterations[2]}, {"4", s.iterations[3]}, {"5+", s.iterations[4]}}},
              {"linearizations", s.linearizations},
              {"jet_evaluations", s.jet_evaluations},
              {"surface_evaluations", {s.surface_evaluations[0], s.surface_evaluations[1]}},
              // work per accepted point (issue 12 item 4): both surfaces' calls over the points
              {"evaluations_per_point",
               s.points > 0 ? static_cast<double>(s.surface_evaluations[0] + s.surface_evaluations[1]) / static_cast<double>(s.points) : 0.0},
              {"corrector_failures", s.corrector_failures},
              {"time_ms", s.time_ms}};
}

// How the start points were found and whether every branch is guaranteed (docs/topology.md).
static json start_search_to_json(const StartPointSearch& s) {
  json regions = json::array();
  for (const UncertainRegion& u : s.uncertain_regions) {
    json box = json::array();
    for (const Interval& i : u.box) box.push_back({i.lo, i.hi});
    regions.push_back(json{{"system", u.system}, {"reason", to_string(u.reason)}, {"box", box}});
  }
  return json{{"method", to_string(s.method)}, {"certified", s.certified},     {"boxes", s.boxes},
              {"time_ms", s.time_ms},          {"uncertain_regions", regions}, {"note", s.note}};
}

namespace {

// The options the trace used (issue 25: the output reported the requested step_length 0, not the
// step used): those run_intersection resolved once against the model (IntersectionRun::used),
// and which of them were automatic. A problem whose surfaces' boxes are disjoint was never
// traced: its options stand as requested, the tolerance resolved.
json options_json(const IntersectionRun& run) {
  const TraceOptions& asked = run.spec.options.trace;
  const TraceOptions& used = run.used.options;
  json automatic = json::array();
  for (const auto& [key, value] : {std::pair<const char*, double>{"step_length", asked.step_length},
                                   {"min_step_length", asked.min_step_length},
                                   {"min_step", asked.min_step},
                                   {"deviation", asked.deviation},
                                   {"tolerance", asked.tolerance}})
    if (value == 0) automatic.push_back(key);
  return json{{"predictor", std::string(to_string(asked.predictor))},
              {"corrector", std::string(to_string(asked.corrector))},
              {"step", std::string(to_string(asked.step))},
              {"step_length", used.step_length},
              {"min_step_length", used.min_step_length},
              {"min_step", used.min_step},
              {"deviation", used.deviation},
              {"tolerance", used.tolerance},
              {"automatic", std::move(automatic)}};
}

}  // namespace

json to_json(const IntersectionRun& run) {
  json curves = json::array();
  for (std::size_t ci = 0; ci < run.result.curves.size(); ++ci) {
    const TracedCurve& c = run.result.curves[ci];
    json points = json::array();
    for (std::size_t i = 0; i < c.points.size(); ++i) {
      json p{{"xyz", vector_json(c.points[i].p)}, {"params", vector_json(c.points[i].x)}};
      if (ci < run.geometry.size()) add_geometry(run.geometry[ci][i], &p);
      points.push_back(std::move(p));
    }
    json ends = c.closed ? json{{"start", end_json(Termination::kClosedLoop, "closed loop")},
                                {"end", end_json(Termination::kClosedLoop, "closed loop")}}
                         : json{{"start", end_json(c.start_end, c.start_message)}, {"end", end_json(c.end_end, c.end_message)}};
    const auto& b = run.network.branches;
    const NetworkBranch* branch = ci < b.size() && b[ci].curve == static_cast<int>(ci) ? &b[ci] : nullptr;
    const json index = branch && branch->rotation.index ? json(*branch->rotation.index) : json(nullptr);
    json curve{{"closed", c.closed}, {"tangential_contact", c.tangential_contact}, {"length", c.length}, {"num_points", c.points.size()}, {"ends", ends},
               {"rotation_index", index}, {"points", std::move(points)}};
    if (ci < run.conics.size()) curve["conic"] = conic_to_json(run.conics[ci]);
    if (ci < run.splines.size() && run.splines[ci]) add_spline(*run.splines[ci], parametric_surface_names(run), &curve);
    curves.push_back(std::move(curve));
  }
  json names = json::array();
  for (const auto& n : run.problem.unknown_names()) names.push_back(n);
  const auto& s = run.spec.surfaces;
  json coincident = false;
  json region = nullptr;
  if (run.coincidence) {
    const Box& b = run.coincidence->region;
    coincident = true;
    region = json{{"min", {b.x.lo, b.y.lo, b.z.lo}}, {"max", {b.x.hi, b.y.hi, b.z.hi}},
                  {"shared_samples", run.coincidence->shared}, {"samples", run.coincidence->samples}};
  }
  return json{{"name", run.spec.name},
              {"surfaces", json::array({s[0], s[1]})},
              {"coincident", coincident},
              {"coincident_region", region},
              {"pair_kind", std::string(to_string(run.spec.kind))},
              {"unknowns", names},
              {"parametric_first", run.spec.swapped ? s[1] : s[0]},
              {"options", options_json(run)},
              {"curves", std::move(curves)},
              {"singular_points", singular_points_to_json(run.result.singular_points)},
              {"isolated_points", singular_points_to_json(run.result.isolated_points)},
              {"topology", curve_network_to_json(run.network)},
              {"stats", stats_to_json(run.result.stats)},
              {"certified", run.result.start_search.certified},
              {"start_points", start_search_to_json(run.result.start_search)},
              {"warnings", run.result.warnings}};
}

void write_json(std::ostream& out, const std::vector<IntersectionRun>& runs) {
  json all = json::array();
  for (const auto& r : runs) all.push_back(to_json(r));
  out << json{{"intersections", std::move(all)}}.dump(1) << "\n";
}

void write_csv(std::ostream& out, const std::vector<IntersectionRun>& runs) {
  out << "intersection,curve,point,closed,x,y,z,u,v,p,q\n";
  for (const auto& r : runs) {
    bool implicit_pair = r.problem.kind() == PairKind::kImplicitImplicit;
    for (std::size_t ci = 0; ci < r.result.curves.size(); ++ci) {
      const TracedCurve& c = r.result.curves[ci];
      for (std::size_t i = 0; i < c.points.size(); ++i) {
        const CurvePoint& p = c.points[i];
        out << r.spec.name << "," << ci << "," << i << "," << (c.closed ? 1 : 0) << "," << shortest(p.p.x()) << ","
            << shortest(p.p.y()) << "," << shortest(p.p.z());
        for (int k = 0; k < 4; ++k) {
          out << ",";
          if (!implicit_pair && k < p.x.size()) out << shortest(p.x[k]);
        }
        out << "\n";
      }
    }
  }
}

void write_obj(std::ostream& out, const std::vector<IntersectionRun>& runs) {
  out << "# ssimarch intersection curves: one polyline object per curve\n";
  long base = 1;
  for (const auto& r : runs) {
    for (std::size_t ci = 0; ci < r.result.curves.size(); ++ci) {
      const TracedCurve& c = r.result.curves[ci];
      out << "o " << r.spec.name << "_curve" << ci << "\n";
      std::size_t n = c.points.size();
      // A closed curve's last point repeats its first: write it once and close the polyline.
      std::size_t m = (c.closed && n > 1) ? n - 1 : n;
      for (std::size_t i = 0; i < m; ++i)
        out << "v " << shortest(c.points[i].p.x()) << " " << shortest(c.points[i].p.y()) << " " << shortest(c.points[i].p.z()) << "\n";
      if (m >= 2) {
        out << "l";
        for (std::size_t i = 0; i < m; ++i) out << " " << base + static_cast<long>(i);
        if (c.closed) out << " " << base;
        out << "\n";
      }
      base += static_cast<long>(m);
    }
  }
}

}  // namespace ssimarch
