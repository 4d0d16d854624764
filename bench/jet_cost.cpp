// The per-point kernels of the marching loop (docs/benchmarks.md, "Marching cost"): CPU time of a
// curve jet of order 4 (what the tracer computes at every accepted point) and of one
// linearisation (each corrector iteration), on Viviani's curve in its three forms and thesis
// pair 1, plus points and jets of a bicubic NURBS surface on its Bezier pieces against de Boor
// on its net (issue 27 item 1), and its interval enclosures (what the certified search
// evaluates: an interval, a gradient over intervals, a nested one) from the pieces' restricted
// control nets against de Boor run in the interval type, with the enclosures' widths (item 2),
// and the elementary functions of order-12 jets (graded recurrences against Horner's rule).
//
//   jet_cost [--reps N]        (cmake --preset bench && cmake --build build-bench --target jet_cost)
//
// Thread CPU time (CLOCK_THREAD_CPUTIME_ID: a machine shared with other work disturbs it far
// less than wall time), best of N repetitions (default 7) of 2000 calls each, in ns per call.
// Written against the problem/ API that both the allocating and the allocation-free versions
// share, so the same source measures before and after a change.
#include <time.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <type_traits>
#include <vector>

#include "ssimarch/problem/closest_point.hpp"
#include "ssimarch/problem/curve_jet.hpp"
#include "ssimarch/problem/gauss_newton.hpp"
#include "ssimarch/problem/problem.hpp"
#include "ssimarch/start/gradient.hpp"
#include "ssimarch/start/interval_number.hpp"
#include "ssimarch/surface/bspline_surface.hpp"
#include "ssimarch/surface/surface.hpp"
#include "testing/surface_pairs.hpp"

using namespace ssimarch;

namespace {

double thread_cpu_ns() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return 1e9 * static_cast<double>(t.tv_sec) + static_cast<double>(t.tv_nsec);
}

// Best time per call of f over reps repetitions of n calls (ns).
template <class F>
double ns_per_call(int reps, int n, F&& f) {
  double best = 1e300;
  for (int r = 0; r < reps; ++r) {
    const double t0 = thread_cpu_ns();
    for (int i = 0; i < n; ++i) f();
    best = std::min(best, (thread_cpu_ns() - t0) / n);
  }
  return best;
}

struct Case {
  std::string name;
  Problem problem;
  Vec3 start;
};

volatile double g_sink = 0;

void problem_rows(int reps) {
  std::vector<Case> cases;
  const Vec3 viviani = testing::viviani(1.0);
  cases.push_back({"viviani PP", Problem(testing::cylinder_f2(), testing::sphere_g2_parametric(), PairKind::kParametricParametric), viviani});
  cases.push_back({"viviani PI", Problem(testing::cylinder_f2(), testing::sphere_g2_implicit(), PairKind::kParametricImplicit), viviani});
  cases.push_back({"viviani II", Problem(testing::sphere_g2_implicit(), testing::cylinder_f2_implicit(), PairKind::kImplicitImplicit), viviani});
  cases.push_back({"ruled-torus PP", Problem(testing::ruled_surface(), testing::torus_g1(), PairKind::kParametricParametric), testing::c1(0.3)});
  std::printf("| pair | curve jet order 4 (ns) | linearisation (ns) |\n|---|---|---|\n");
  for (const Case& c : cases) {
    const auto near = unknowns_near(c.problem, c.start);
    if (!near) {
      std::printf("| %s | no start | |\n", c.name.c_str());
      continue;
    }
    const CorrectorResult r = gauss_newton(c.problem, *near, CorrectorOptions{});
    const VecX x = r.x;
    const double jet = ns_per_call(reps, 2000, [&] { g_sink = curve_jet_dynamic(c.problem, x, 4).rank_ratio; });
    const double lin = ns_per_call(reps, 2000, [&] { g_sink = c.problem.linearize(x).distance; });
    std::printf("| %s | %.0f | %.0f |\n", c.name.c_str(), jet, lin);
  }
}

// One evaluation kind on the surface's Bezier pieces (issue 27) and by de Boor on the net in the
// number type itself (the evaluation before issue 27, kept for interval types).
template <class T>
void nurbs_row(const char* name, const BSplineSurface& s, int reps, const T& u, const T& v) {
  const double pieces = ns_per_call(reps, 2000, [&] { g_sink = primal(s.point(u, v).x); });
  const double de_boor = ns_per_call(reps, 2000, [&] { g_sink = primal(s.point_de_boor(u, v).x); });
  std::printf("| %s | %.0f | %.0f | %.1f |\n", name, pieces, de_boor, de_boor / pieces);
}

// Bicubic rational B-spline, 6 x 6 control points, two interior knots each way.
BSplineSurface bicubic_nurbs() {
  const std::vector<double> U{0, 0, 0, 0, 0.4, 0.7, 1, 1, 1, 1};
  ControlNet P(6, std::vector<Vec3>(6));
  WeightNet W(6, std::vector<double>(6));
  for (std::size_t i = 0; i < 6; ++i)
    for (std::size_t j = 0; j < 6; ++j) {
      P[i][j] = Vec3(static_cast<double>(i), static_cast<double>(j), std::sin(static_cast<double>(i + 2 * j)));
      W[i][j] = 1.0 + 0.1 * static_cast<double>((i + j) % 3);
    }
  return BSplineSurface(3, 3, U, U, P, W);
}

void nurbs_rows(int reps) {
  const BSplineSurface s = bicubic_nurbs();
  const double u0 = 0.55, v0 = 0.3;
  std::printf("\n| bicubic NURBS point (ns) | Bezier pieces | de Boor | ratio |\n|---|---|---|---|\n");
  nurbs_row("double", s, reps, u0, v0);
  using J1 = Jet<2, 1>;
  using J2 = Jet<2, 2>;
  using J4 = Jet<2, 4>;
  using J12 = Jet<2, 12>;
  nurbs_row("Jet<2,1>", s, reps, J1::variable(0, u0), J1::variable(1, v0));
  nurbs_row("Jet<2,2>", s, reps, J2::variable(0, u0), J2::variable(1, v0));
  nurbs_row("Jet<2,4>", s, reps, J4::variable(0, u0), J4::variable(1, v0));
  nurbs_row("Jet<2,12>", s, reps, J12::variable(0, u0), J12::variable(1, v0));
  // What the singular-point analysis substitutes: the parameters as jets of a local chart.
  const J12 cu12 = J12::variable(0, u0) + 0.3 * J12::variable(1, 0.0) * J12::variable(0, 0.0),
            cv12 = J12::variable(1, v0) - 0.2 * J12::variable(0, 0.0) * J12::variable(0, 0.0);
  nurbs_row("Jet<2,12> (chart)", s, reps, cu12, cv12);
  // What the curve jet substitutes: each parameter a Taylor series in the arc length.
  Taylor<4> cu(u0), cv(v0);
  for (int k = 1; k <= 4; ++k) {
    cu[k] = 0.3 / k;
    cv[k] = -0.2 / k;
  }
  nurbs_row("Taylor<4> (curve jet)", s, reps, cu, cv);
  using L = Jet<4, 1>;  // a linearisation of a parametric-parametric pair: 4 unknowns
  nurbs_row("Jet<4,1> (linearisation)", s, reps, L::variable(2, u0), L::variable(3, v0));
}

// One interval type on a box of half-width h around (u0, v0): time per call and the width of
// the z enclosure's value, restricted control nets against de Boor in the interval type (de Boor
// chooses its span from the box's midpoint: sound only inside one knot span).
template <class T>
void interval_row(const char* name, const BSplineSurface& s, int reps, double u0, double v0, double h) {
  using I = IntervalNumber;
  T u, v;
  if constexpr (std::is_same_v<T, I>) {
    u = I(u0 - h, u0 + h);
    v = I(v0 - h, v0 + h);
  } else if constexpr (std::is_same_v<T, Gradient<I, 2>>) {
    u = T(I(u0 - h, u0 + h), 0);
    v = T(I(v0 - h, v0 + h), 1);
  } else {
    u = T(Gradient<I, 2>(I(u0 - h, u0 + h), 0), 0);
    v = T(Gradient<I, 2>(I(v0 - h, v0 + h), 1), 1);
  }
  const auto width = [](const auto& z) { return internal::innermost(z).width(); };
  const double nets = ns_per_call(reps, 200, [&] { g_sink = primal(s.point(u, v).z); });
  const double de_boor = ns_per_call(reps, 200, [&] { g_sink = primal(s.point_de_boor(u, v).z); });
  std::printf("| %s, h = %g | %.0f | %.0f | %.2g | %.2g |\n", name, h, nets, de_boor, width(s.point(u, v).z),
              width(s.point_de_boor(u, v).z));
}

void interval_rows(int reps) {
  const BSplineSurface s = bicubic_nurbs();
  std::printf(
      "\n| bicubic NURBS on a box inside one span (ns) | control nets | de Boor in T | z width, nets | "
      "z width, de Boor |\n|---|---|---|---|---|\n");
  using I = IntervalNumber;
  for (double h : {0.1, 0.01, 0.001}) {
    interval_row<I>("interval", s, reps, 0.55, 0.55, h);
    interval_row<Gradient<I, 2>>("Gradient<I,2>", s, reps, 0.55, 0.55, h);
    interval_row<Gradient<Gradient<I, 2>, 2>>("nested gradient", s, reps, 0.55, 0.55, h);
  }
}

// Elementary functions of an order-12 jet in two variables (the local curves' jets, built at
// every singular-point analysis, contact point and hunt sample): the graded recurrences of
// core/jet.hpp against Horner's rule with the univariate series (Jet::apply), and a torus's
// point as such a jet (four of them).
void elementary_rows(int reps) {
  using J = Jet<2, 12>;
  const J s = J::variable(0, 0.7), t = J::variable(1, -0.2);
  J a = 1.1 + 0.3 * s + s * t - 0.2 * t * t;
  double sink = 0;
  std::printf("\n%-34s %12s %12s\n", "Jet<2,12> function", "recurrence", "Horner");
  const auto row = [&](const char* name, auto&& fast, auto&& horner) {
    const double f = ns_per_call(reps, 200, [&] {
      a[2] += 1e-12;
      sink += fast(a)[50];
    });
    const double h = ns_per_call(reps, 200, [&] {
      a[2] += 1e-12;
      sink += horner(a)[50];
    });
    std::printf("%-34s %12.0f %12.0f\n", name, f, h);
  };
  row(
      "sin", [](const J& x) { return sin(x); }, [](const J& x) { return J::apply(x, internal::sin<12>(x.value())); });
  row(
      "exp", [](const J& x) { return exp(x); }, [](const J& x) { return J::apply(x, internal::exp<12>(x.value())); });
  row(
      "sqrt", [](const J& x) { return sqrt(x); },
      [](const J& x) { return J::apply(x, internal::sqrt<12>(x.value())); });
  const Surface torus = Surface(Torus(Vec3::Zero(), Vec3::UnitZ(), 2.0, 1.0));
  const double p = ns_per_call(reps, 200, [&] {
    a[2] += 1e-12;
    sink += torus.point(a, a).x[50];
  });
  std::printf("%-34s %12.0f\n", "torus point (4 sin/cos)", p);
  if (sink == 42) std::printf(" ");
}

}  // namespace

int main(int argc, char** argv) {
  int reps = 7;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--reps") == 0 && i + 1 < argc) reps = std::max(1, std::atoi(argv[++i]));
  problem_rows(reps);
  nurbs_rows(reps);
  interval_rows(reps);
  elementary_rows(reps);
  return 0;
}
