// Generates the accuracy table of docs/geometry.md: the error of every geometry method against
// the exact Frenet values of the closed-form curve, along the thesis' ruled surface-torus curve
// C1 and towards the sphere-cylinder double point C2(0), as sin(theta) -> 0.
//
//   cmake --build build --target geometry_table && build/bin/geometry_table > /tmp/table.md
//
// Points are taken on the closed-form curves (exact to rounding) and, in a last pass, moved off
// the curve by 1e-10 model units along N_1 (what a tracer's corrector tolerance leaves); the
// estimate's samples are the curve points at parameter offsets -2ds, -ds, +ds (the thesis'
// Table 3.3 set-up, one more sample back for the three-point circle).
#include <cstdio>
#include <functional>
#include <string>
#include <vector>

#include "geometry/test_curves.hpp"
#include "ssimarch/geometry/intersection_geometry.hpp"
#include "ssimarch/surface/expr_surface.hpp"

using namespace ssimarch;
using namespace ssimarch::testing;

namespace {

const double kPi = std::numbers::pi;
const Box kBox{{-8, 8}, {-8, 8}, {-8, 8}};

struct Pair {
  Problem param;                         // the thesis' parametric pair
  std::optional<Problem> implicit_pair;  // both implicit (willmore), where the thesis pair has one
  std::function<VecX(double)> x;         // unknowns of `param` at curve parameter s
  std::function<Vec3(double)> point;
  std::function<CurveGeometry(double)> exact;
};

Pair pair1() {
  Surface f1 = ExprParametric::compile({"(4+cos(4*u))*cos(u) + v*(cos(4*u)+sin(4*u))*cos(u)",
                                        "(4+cos(4*u))*sin(u) + v*(cos(4*u)+sin(4*u))*sin(u)",
                                        "sin(4*u) + v*(sin(4*u)-cos(4*u))"},
                                       {{0, 2 * kPi}, {-0.5, 0.5}, true, false}, {});
  Surface g1 = ExprParametric::compile({"(4+cos(u))*sin(v)", "(4+cos(u))*cos(v)", "sin(u)"},
                                       {{0, 2 * kPi}, {0, 2 * kPi}, true, true}, {});
  return {Problem(f1, g1, PairKind::kParametricParametric), std::nullopt,
          [](double s) {
            VecX x(4);
            x << s, 0.0, 4 * s, kPi / 2 - s;
            return x;
          },
          [](double s) { return curve_point(TorusKnot{}, s); }, [](double s) { return exact_frenet(TorusKnot{}, s); }};
}

Pair pair2() {
  Surface f2 = ExprParametric::compile({"cos(u)", "sin(u)-1", "v"}, {{0, 2 * kPi}, {-3, 3}, true, false}, {});
  Surface g2 = ExprParametric::compile({"-1+2*cos(u)*cos(v)", "-1+2*cos(u)*sin(v)", "2*sin(u)"},
                                       {{-kPi / 2, kPi / 2}, {-kPi, kPi}, false, true}, {});
  Problem ii(ExprImplicit::compile("x^2+(y+1)^2-1", kBox, {}), ExprImplicit::compile("(x+1)^2+(y+1)^2+z^2-4", kBox, {}),
             PairKind::kImplicitImplicit);
  return {Problem(f2, g2, PairKind::kParametricParametric), ii,
          [](double s) {
            VecX x(4);
            x << s, 2 * std::sin(s / 2), s / 2, s / 2;
            return x;
          },
          [](double s) { return curve_point(CurveC2{}, s); }, [](double s) { return exact_frenet(CurveC2{}, s); }};
}

struct Method {
  const char* name;
  GeometryMethod m;
  bool needs_samples;
};
const std::vector<Method> kMethods{{"exact", GeometryMethod::kExact, false},
                                   {"ye-maekawa", GeometryMethod::kYeMaekawa, false},
                                   {"stoyanov", GeometryMethod::kStoyanov, false},
                                   {"willmore", GeometryMethod::kWillmore, false},
                                   {"estimate", GeometryMethod::kEstimate, true},
                                   {"barnhill-kersey", GeometryMethod::kBarnhillKersey, true},
                                   {"mixed", GeometryMethod::kMixed, true}};

// Moves x (implicit-implicit unknowns) off the curve by `offset` along N_1.
VecX perturb(const Problem& pb, const VecX& x, double offset) {
  if (offset == 0 || pb.kind() != PairKind::kImplicitImplicit) return x;
  auto l = surface_locals(pb, x);
  return x + offset * unit_normal(l->first);
}

// Largest of |d kappa|, |d tau|, |d kappa'| (what is defined), or the status.
std::string error_cell(const CurveGeometry& g, const CurveGeometry& exact) {
  char buf[64];
  if (!std::isfinite(g.kappa)) {
    std::snprintf(buf, sizeof buf, "(%s)", std::string(to_string(g.status)).c_str());
    return buf;
  }
  double e = std::fabs(g.kappa - exact.kappa);
  bool third = std::isfinite(g.tau) && std::isfinite(g.kappa_prime);
  if (third) e = std::max({e, std::fabs(g.tau - exact.tau), std::fabs(g.kappa_prime - exact.kappa_prime)});
  std::snprintf(buf, sizeof buf, "%.1e%s", e, third ? "" : " (kappa only)");
  return buf;
}

void table(const char* title, Pair& pair, const std::vector<double>& params, double ds, double offset) {
  std::printf("\n%s\n\n| s | sin(theta) |", title);
  for (const Method& m : kMethods) std::printf(" %s |", m.name);
  std::printf("\n|---|---|");
  for (std::size_t i = 0; i < kMethods.size(); ++i) std::printf("---|");
  std::printf("\n");
  for (double s : params) {
    CurveGeometry exact = pair.exact(s);
    VecX x = perturb(pair.param, pair.x(s), offset);
    auto l = surface_locals(pair.param, x);
    double sin_theta = unit_normal(l->first).cross(unit_normal(l->second)).norm();
    std::printf("| %.3g | %.2e |", s, sin_theta);
    for (const Method& m : kMethods) {
      GeometryContext ctx;
      ctx.orientation = exact.t;
      if (m.needs_samples) {
        ctx.previous = {perturb(pair.param, pair.x(s - 2 * ds), offset), perturb(pair.param, pair.x(s - ds), offset)};
        ctx.next = {perturb(pair.param, pair.x(s + ds), offset)};
      }
      CurveGeometry g;
      if (m.m == GeometryMethod::kWillmore) {
        if (!pair.implicit_pair) {
          std::printf(" n/a |");
          continue;
        }
        Vec3 p = pair.point(s) + offset * unit_normal(l->first);
        g = evaluate_geometry(*pair.implicit_pair, p, m.m, ctx);
      } else {
        g = evaluate_geometry(pair.param, x, m.m, ctx);
      }
      std::printf(" %s |", error_cell(g, exact).c_str());
    }
    std::printf("\n");
  }
}

}  // namespace

int main() {
  Pair p1 = pair1(), p2 = pair2();
  // C1: where along the curve are the normals closest to parallel?
  double s_min = 0, sin_min = 2;
  for (int i = 0; i <= 20000; ++i) {
    double s = 2 * kPi * i / 20000;
    auto l = surface_locals(p1.param, p1.x(s));
    double v = unit_normal(l->first).cross(unit_normal(l->second)).norm();
    if (v < sin_min) {
      sin_min = v;
      s_min = s;
    }
  }
  std::printf("C1: min sin(theta) = %.3f at s = %.4f (20001 samples of [0, 2 pi])\n", sin_min, s_min);
  const double ds = 0.01;
  std::vector<double> c1;
  for (int k = 0; k <= 8; ++k) c1.push_back(k * kPi / 16);  // a quarter period of C1 (symmetry)
  std::vector<double> c2{0.5, 1e-1, 1e-2, 1e-3, 1e-4, 1e-5, 1e-6, 1e-7, 1e-8, 0.0};
  std::printf("\nError = max(|d kappa|, |d tau|, |d kappa'|) against the closed-form curve; estimate, "
              "barnhill-kersey and mixed use the samples at s - 2 ds, s - ds, s + ds, ds = %.2g.\n", ds);
  table("Ruled surface / torus (thesis pair 1), points on the curve (transversal everywhere):", p1, c1, ds, 0.0);
  table("Cylinder / sphere (pair 2) towards the double point C2(0), points on the curve:", p2, c2, ds, 0.0);
  // Off-curve points on the implicit-implicit form of pair 2: x moved by 1e-10 along N_1, i.e.
  // 1e-10 off the cylinder (a tracer's tolerance).
  Pair p2i{*p2.implicit_pair, p2.implicit_pair, [](double s) { return VecX(curve_point(CurveC2{}, s)); }, p2.point,
           p2.exact};
  table("Cylinder / sphere (both implicit) towards C2(0), points and samples 1e-10 off the cylinder:", p2i, c2, ds,
        1e-10);
  return 0;
}
