// Certified B-splines against OpenCASCADE's approximation of the same intersection curves
// (issue 14 "Measure and publish"; docs/benchmarks.md, "CAD curves"). For each peer case and
// tolerance tol = 1e-7, 1e-9, 1e-11 (model length):
//
//   OCCT      GeomInt_IntSS(S1, S2, tol, Approx = true) on the case's exact B-spline surfaces
//             (occt_bspline: every curve goes through OCCT's approximation; on the analytic
//             variant quadric pairs come back as conics): curves, poles of its B-spline curves,
//             its TolReached3d, the deviation measured, wall time;
//   ssimarch  the curves traced coarsely (constant step scale/25, as bench/spline-table) with
//             option bspline at bspline_tolerance = tol: curves, control points of the 3D
//             B-splines, the reported max_deviation, the deviation measured, wall time of the run.
//
// The deviation measured is the same for both: the largest distance from the two surfaces of
// the scene (peer_measure.hpp: |f| / |grad f| on implicit forms, the nearest point on parametric
// ones) over 2000 points per curve, evenly spaced in the curve's parameter.
//
//   occt_approx_table [--case NAME] [--reps N]     (Markdown on stdout)
#include <Geom_BSplineCurve.hxx>
#include <Geom_Curve.hxx>
#include <Geom_TrimmedCurve.hxx>
#include <GeomInt_IntSS.hxx>
#include <Standard_Failure.hxx>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "occt_surfaces.hpp"
#include "peer_measure.hpp"
#include "ssimarch/io/scene.hpp"
#include "ssimarch/pipeline/option_table.hpp"
#include "ssimarch/pipeline/trace_job.hpp"

namespace {

using namespace ssimarch;

constexpr int kSamplesPerCurve = 2000;
const double kTolerances[] = {1e-7, 1e-9, 1e-11};
const char* kCases[] = {"viviani_thesis", "viviani_unit", "torus_ruled_knot", "plane_ellipsoid", "two_cylinders",
                        "paraboloid_cylinder", "ellipsoid_ellipsoid", "devil_curve", "occt_bug21494_2", "occt_bug33244"};

struct Answer {
  int curves = 0;
  int poles = 0;           // control points of the B-spline curves
  int other = 0;           // curves that are not B-splines (conics, lines)
  double reported = 0;     // OCCT's TolReached3d, ssimarch's largest max_deviation
  double measured = 0;     // largest distance of a sample from the two surfaces
  double ms = 0;
  std::string note;
};

double elapsed_ms(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
}

Answer run_occt(const peers::OcctPair& pair, const Surface& a, const Surface& b, double tol) {
  Answer out;
  try {
    const auto t0 = std::chrono::steady_clock::now();
    GeomInt_IntSS inter(pair.first, pair.second, tol, Standard_True, Standard_False, Standard_False);
    out.ms = elapsed_ms(t0);
    if (!inter.IsDone()) {
      out.note = "not done";
      return out;
    }
    out.reported = inter.TolReached3d();
    out.curves = inter.NbLines();
    for (int i = 1; i <= inter.NbLines(); ++i) {
      Handle(Geom_Curve) c = inter.Line(i);
      const double f = c->FirstParameter(), l = c->LastParameter();
      Handle(Geom_TrimmedCurve) trimmed = Handle(Geom_TrimmedCurve)::DownCast(c);
      Handle(Geom_BSplineCurve) bs = Handle(Geom_BSplineCurve)::DownCast(trimmed.IsNull() ? c : trimmed->BasisCurve());
      if (bs.IsNull()) ++out.other;
      else out.poles += bs->NbPoles();
      if (!std::isfinite(f) || !std::isfinite(l)) {
        out.note = "unbounded curve";
        continue;
      }
      for (int k = 0; k <= kSamplesPerCurve; ++k) {
        const gp_Pnt p = c->Value(f + (l - f) * k / kSamplesPerCurve);
        out.measured = std::max(out.measured, peers::residual(a, b, Vec3(p.X(), p.Y(), p.Z())));
      }
    }
  } catch (const Standard_Failure& e) {
    out.note = std::string("exception: ") + e.GetMessageString();
  }
  return out;
}

void set(const char* key, const OptionValue& value, IntersectionSpec* spec) {
  apply_trace_option(*find_trace_option(key), value, Constants{}, "occt_approx_table", &spec->options);
}

Answer run_ssimarch(const Scene& scene, IntersectionSpec spec, double tol) {
  const double scale = scene.problem(spec).scale();
  spec.options.closed_form = false;  // trace the curve, as the OCCT side approximates it
  set("step", std::string("constant"), &spec);
  set("step_length", scale / 25, &spec);
  set("bspline", std::string("true"), &spec);
  set("bspline_tolerance", tol, &spec);
  Answer out;
  const auto t0 = std::chrono::steady_clock::now();
  const IntersectionRun run = run_intersection(scene, spec);
  out.ms = elapsed_ms(t0);
  const Surface& a = scene.surface(spec.surfaces[0]);
  const Surface& b = scene.surface(spec.surfaces[1]);
  for (const std::optional<CurveSpline>& s : run.splines) {
    if (!s) continue;
    ++out.curves;
    out.poles += static_cast<int>(s->curve.control_points.size());
    out.reported = std::max(out.reported, s->max_deviation);
    if (!s->within_tolerance) out.note = "bound above tolerance";
    for (int k = 0; k <= kSamplesPerCurve; ++k) {
      const double t = s->curve.start() + (s->curve.end() - s->curve.start()) * k / kSamplesPerCurve;
      out.measured = std::max(out.measured, peers::residual(a, b, Vec3(s->curve.at(t))));
    }
  }
  return out;
}

std::string cell(const Answer& x, bool occt) {
  char buf[200];
  // A run that threw or found nothing: the reason in every cell, no zeros that read as answers.
  if (x.curves == 0 && !x.note.empty()) return x.note + " | - | - | - | -";
  if (occt && x.other) std::snprintf(buf, sizeof buf, "%d (%d not B-spline)", x.curves, x.other);
  else std::snprintf(buf, sizeof buf, "%d", x.curves);
  std::string s = buf;
  std::snprintf(buf, sizeof buf, " | %d | %.1e | %.1e | %.3g", x.poles, x.reported, x.measured, x.ms);
  s += buf;
  if (!x.note.empty()) s += " (" + x.note + ")";
  return s;
}

}  // namespace

int main(int argc, char** argv) {
  std::string only;
  int reps = 3;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--case")) only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--reps")) reps = std::max(1, std::atoi(argv[i + 1]));
  }
  std::printf("| case | tol | OCCT curves | OCCT poles | OCCT TolReached3d | OCCT measured | OCCT ms |"
              " ssimarch curves | ssimarch ctrl pts | ssimarch max_deviation | ssimarch measured | ssimarch ms |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const char* name : kCases) {
    if (!only.empty() && only != name) continue;
    const Scene scene = load_scene(std::string(SSIMARCH_SOURCE_DIR) + "/bench/peers/scenes/" + name + ".json");
    const IntersectionSpec spec = scene.intersections.at(0);
    peers::OcctPair pair = peers::occt_bspline(name);
    if (pair.first.IsNull() || pair.second.IsNull()) pair = peers::occt_analytic(name);
    const Surface& a = scene.surface(spec.surfaces[0]);
    const Surface& b = scene.surface(spec.surfaces[1]);
    for (double tol : kTolerances) {
      // The median time of `reps` runs each (the answers do not change between runs).
      Answer o, s;
      std::vector<double> occt_ms, ours_ms;
      for (int r = 0; r < reps; ++r) {
        o = run_occt(pair, a, b, tol);
        s = run_ssimarch(scene, spec, tol);
        occt_ms.push_back(o.ms);
        ours_ms.push_back(s.ms);
      }
      o.ms = peers::median(occt_ms);
      s.ms = peers::median(ours_ms);
      std::printf("| %s | %g | %s | %s |\n", name, tol, cell(o, true).c_str(), cell(s, false).c_str());
      std::fflush(stdout);
    }
  }
  return 0;
}
