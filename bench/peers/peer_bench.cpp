// Side-by-side benchmark: OpenCASCADE (GeomAPI_IntSS, analytic and B-spline input), SISL (s1859 +
// s1310) and ssimarch (analytic input with and without its closed forms, and OpenCASCADE's B-spline
// surfaces in both orders: ssimarch_bspline_scene.hpp) on the peer cases in one process,
// OpenCASCADE and ssimarch interleaved, SISL after them (docs/benchmarks.md, "Peers").
//
//   peer_bench [--reps N] [--case NAME] [--scenes DIR] [--write-bspline-scenes DIR]
//
// Prints Markdown: per case and engine, curves (+ isolated points), closed curves, |total length -
// exact|, the largest distance of a sampled point from the two surfaces, the median and fastest
// time, and for ssimarch OpenCASCADE-analytic time / ssimarch time (x) and OpenCASCADE-B-spline
// time / ssimarch time (xB), both of medians.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <string>
#include <vector>

#include "peer_engines.hpp"
#include "ssimarch_bspline_scene.hpp"
#include "ssimarch/io/scene.hpp"

namespace {

using namespace peers;

struct Case {
  const char* name;
  double exact_length;
  int exact_components;
  const char* source;
};

// Exact lengths: shared/peers/cases.jsonl; the occt_* cases: closed forms in the comments, and
// bench/peers/reference_lengths.py for bug33244.
const Case kCases[] = {
    {"viviani_thesis", 15.2807911542, 1, "cases.jsonl"},
    {"viviani_thesis_xpole", 15.2807911542, 1, "cases.jsonl"},
    {"viviani_unit", 7.64039557709, 1, "cases.jsonl"},
    {"torus_ruled_knot", 35.6831156393, 1, "cases.jsonl"},
    {"plane_ellipsoid", 11.0376087706, 1, "cases.jsonl"},
    {"two_cylinders", 15.2807911555, 2, "cases.jsonl"},
    {"paraboloid_cylinder", 12.5663706139, 1, "cases.jsonl"},
    {"ellipsoid_ellipsoid", 21.2912863011, 2, "cases.jsonl"},
    {"devil_curve", 13.4552889635, 4, "cases.jsonl"},
    {"sphere_plane_tangent", 0, 1, "cases.jsonl"},
    {"cylinder_plane_tangent", 4, 1, "cases.jsonl"},
    {"occt_bug21494_2", 2 * M_PI * 120 / 13, 2, "OCCT tests/lowalgos/intss/bug21494_2: circle r = 120/13 + apex point"},
    {"occt_bug24694_7", 20 * M_PI, 1, "OCCT tests/lowalgos/intss/bug24694_7: equator, tangential"},
    {"occt_bug28222_2", 2 * 77.0906952055927526, 2,
     "OCCT tests/lowalgos/intss/bug28222_2: two loops, reference_lengths.py"},
    {"occt_bug33244", 13.9478623648, 2, "OCCT tests/lowalgos/intss/bug33244 (trimmed |h| <= 3): reference_lengths.py"},
};

enum Engine {
  kOcctAnalytic,
  kOcctBspline,
  kSisl,
  kSsimarch,
  kSsimarchTraced,
  kSsimarchBspline,
  kSsimarchBsplineSwapped,
  kEngines
};
const char* kEngineNames[kEngines] = {"OCCT analytic",
                                      "OCCT B-spline",
                                      "SISL",
                                      "ssimarch",
                                      "ssimarch traced",
                                      "ssimarch B-spline",
                                      "ssimarch B-spline swapped"};

struct Row {
  Outcome outcome;
  std::vector<double> ms;
};

struct Loaded {
  const Case* c;
  ssimarch::Scene scene;
  ssimarch::IntersectionSpec spec, traced;
  OcctPair analytic, bspline;
  ssimarch::Scene bspline_scene;  // OpenCASCADE's B-splines as given and swapped
  Row rows[kEngines];
};

// Runs the engines of [from, to) once on one case.
void run_once(Loaded* l, bool first, int from, int to) {
  const ssimarch::Surface& a = l->scene.surface(l->spec.surfaces[0]);
  const ssimarch::Surface& b = l->scene.surface(l->spec.surfaces[1]);
  for (int e = from; e < to; ++e) {
    double ms = NAN;
    Outcome o;
    switch (e) {
      case kOcctAnalytic: o = run_occt(l->analytic, a, b, &ms); break;
      case kOcctBspline: o = run_occt(l->bspline, a, b, &ms); break;
      case kSisl: o = run_sisl(l->bspline, a, b, &ms); break;
      case kSsimarch: o = run_ssimarch(l->scene, l->spec, &ms); break;
      case kSsimarchTraced: o = run_ssimarch(l->scene, l->traced, &ms); break;
      case kSsimarchBspline: o = run_ssimarch(l->bspline_scene, l->bspline_scene.intersections.at(0), &ms); break;
      default: o = run_ssimarch(l->bspline_scene, l->bspline_scene.intersections.at(1), &ms); break;
    }
    if (first) {
      l->rows[e].outcome = o;
      std::fprintf(stderr, "%s / %s: %.3g ms\n", l->c->name, kEngineNames[e], ms);
    }
    if (std::isfinite(ms)) l->rows[e].ms.push_back(ms);
  }
}

// Fastest of the repetitions: on a loaded machine the median moves with the load, while the fastest
// run is the closest to the call's own cost (both are printed; ratios of one run are what to read).
double best(const std::vector<double>& t) { return t.empty() ? NAN : *std::min_element(t.begin(), t.end()); }

// One cell: "curves[+isolated points p]/closed, dL, res, median ms (best ms)[, x ratio[ / xB ratio]][ (note)]":
// x = OpenCASCADE-analytic median / this median, xB = OpenCASCADE-B-spline median / this median
// (issue 12's targets: x >= 5 and xB >= 10).
std::string cell(const Outcome& o, double exact_length, const std::vector<double>& ms, double occt, double occt_bspline) {
  const double t = median(ms);
  char buf[200];
  std::snprintf(buf, sizeof buf, "%d", o.curves);
  std::string s = buf;
  if (o.isolated) {
    std::snprintf(buf, sizeof buf, "+%dp", o.isolated);
    s += buf;
  }
  std::snprintf(buf, sizeof buf, "/%d, dL %.1e, res %.0e, %.3g ms (best %.3g)", o.closed, std::fabs(o.length - exact_length),
                o.residual, t, best(ms));
  s += buf;
  if (std::isfinite(occt / t)) {
    std::snprintf(buf, sizeof buf, ", x%.3g", occt / t);
    s += buf;
  }
  if (std::isfinite(occt_bspline / t)) {
    std::snprintf(buf, sizeof buf, "%sxB %.3g", std::isfinite(occt / t) ? " / " : ", ", occt_bspline / t);
    s += buf;
  }
  if (!o.note.empty()) s.append(" (").append(o.note).append(")");
  return s;
}

void print(const Loaded& l) {
  const double occt = median(l.rows[kOcctAnalytic].ms), occt_bspline = median(l.rows[kOcctBspline].ms);
  std::printf("| %s | %.10g (%d) |", l.c->name, l.c->exact_length, l.c->exact_components);
  for (int e = 0; e < kEngines; ++e) {
    const bool ours = e >= kSsimarch;
    const std::string none = l.rows[e].outcome.note.empty() ? "-" : l.rows[e].outcome.note;
    const std::string text = cell(l.rows[e].outcome, l.c->exact_length, l.rows[e].ms, ours ? occt : NAN, ours ? occt_bspline : NAN);
    std::printf(" %s |", l.rows[e].ms.empty() ? none.c_str() : text.c_str());
  }
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 7;
  std::string only, write_to, dir = std::string(SSIMARCH_SOURCE_DIR) + "/bench/peers/scenes";
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--reps")) reps = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--case")) only = argv[i + 1];
    else if (!std::strcmp(argv[i], "--scenes")) dir = argv[i + 1];
    else if (!std::strcmp(argv[i], "--write-bspline-scenes"))
      write_to = argv[i + 1];
  }
  std::vector<Loaded> cases;
  for (const Case& c : kCases) {
    if (!only.empty() && only != c.name) continue;
    const std::string path = dir + "/" + c.name + ".json";
    Loaded l{&c, ssimarch::load_scene(path), {}, {}, occt_analytic(c.name), occt_bspline(c.name), {}, {}};
    const nlohmann::json bspline_scene = ssimarch_bspline_scene_json(path, l.bspline);
    if (!write_to.empty()) std::ofstream(write_to + "/" + c.name + "_bspline.json") << bspline_scene.dump(1);
    l.bspline_scene = ssimarch::parse_scene(bspline_scene.dump(), path + " (B-spline form)");
    l.spec = l.scene.intersections.at(0);
    l.traced = l.spec;
    l.traced.options.closed_form = false;
    cases.push_back(std::move(l));
  }
  // OpenCASCADE and ssimarch interleaved: every engine on every case, then again. SISL runs in a
  // forked child (sisl_engine.cpp), and after a fork every page of this process is copy-on-write:
  // the engine run next paid for re-faulting its heap (3-5 ms, malloc_consolidate and page faults in
  // `perf record`), so SISL's repetitions come after all the others.
  const int engines[] = {kOcctAnalytic,   kOcctBspline,     kSsimarch,
                         kSsimarchTraced, kSsimarchBspline, kSsimarchBsplineSwapped};
  for (int r = 0; r < reps; ++r)
    for (Loaded& l : cases)
      for (int e : engines) run_once(&l, r == 0, e, e + 1);
  for (int r = 0; r < reps; ++r)
    for (Loaded& l : cases) run_once(&l, r == 0, kSisl, kSisl + 1);
  std::printf("| case | exact length (components) |");
  for (const char* e : kEngineNames) std::printf(" %s |", e);
  std::printf("\n|---|---|");
  for (int e = 0; e < kEngines; ++e) std::printf("---|");
  std::printf("\n");
  for (const Loaded& l : cases) print(l);
  return 0;
}
